// The editing differential test (edit_diff.cpp): one operation in vertex ids that every
// library shares, and each peer (OpenMesh, CGAL) behind one small interface, so that their
// heavy headers stay in one translation unit each (edit_openmesh.cpp, edit_cgal.cpp).
//
// Shared vertex ids: vertex i of the built topomesh is i in every library (the peers are
// built from its triangles); the vertex an edge split adds gets the id the operation names
// (the next unused one). Ids differ inside the libraries (CGAL recycles removed slots,
// garbage collection renumbers), so each peer keeps its handle per shared id and a vertex
// property holding the shared id.
#pragma once

#include "peers.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace diffmesh {

enum class OpKind : uint8_t { Flip, Split, Collapse, Remove };

// Every operation names triangle (a, b, c) and its half-edge a -> b: a flip turns the edge
// a-b, a split adds vertex `fresh` on it, a collapse merges b into a (a stays), a removal
// removes the triangle. A peer that has no such triangle answers Missing.
struct EditOp {
  OpKind kind = OpKind::Flip;
  uint32_t a = 0, b = 0, c = 0;
  uint32_t fresh = 0;
};

enum class Outcome : uint8_t { Refused, Done, Missing };

// Live counts; `isolated` are the vertices without a face; the boundary edges and the
// loops they form.
struct EditCounts {
  size_t vertices = 0, edges = 0, faces = 0, isolated = 0;
  size_t boundary_edges = 0, boundary_loops = 0;
  long long euler() const { return (long long)vertices - (long long)edges + (long long)faces; }
};

// A triangle in shared ids, rotated to start at its smallest id (orientation kept).
using Tri = std::array<uint32_t, 3>;
inline Tri canonical(Tri t) {
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

class EditPeer {
public:
  virtual ~EditPeer() = default;
  virtual const char *name() const = 0;
  // Decides with the library's own check, then applies the operation when accepted.
  virtual Outcome apply(const EditOp &op) = 0;
  virtual void collect_garbage() = 0;
  virtual EditCounts counts() const = 0;
  // The triangles in shared ids, canonical and sorted.
  virtual std::vector<Tri> triangles() const = 0;
  // The shared ids of the live vertices with no face (`isolated`) or with one, sorted.
  virtual std::vector<uint32_t> vertex_ids(bool isolated) const = 0;
};

// The peers built from `in` (every triangle must be accepted: check counts()).
std::unique_ptr<EditPeer> openmesh_editor(const PeerInput &in);
std::unique_ptr<EditPeer> cgal_editor(const PeerInput &in);

} // namespace diffmesh
