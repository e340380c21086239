// The two peers, OpenMesh (TriMesh, ArrayKernel) and CGAL (Surface_mesh), behind one small
// interface so that their heavy headers stay in one translation unit each.
#pragma once

#include "answers.hpp"
#include "bench_util.hpp"

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <memory>
#include <vector>

namespace diffmesh {

// The same arrays for every library. Degenerate triangles are not offered to the peers
// (CGAL refuses them; OpenMesh corrupts itself on them) and are counted as skipped.
struct PeerInput {
  size_t n_vertices = 0;
  const double *positions = nullptr; // 3 per vertex
  const uint32_t *triangles = nullptr;
  size_t n_triangles = 0;
};

// Builds the peer from `in` and returns every answer in common ids.
Answers openmesh_answers(const PeerInput &in, PeerBuild &build);
Answers cgal_answers(const PeerInput &in, PeerBuild &build);

// The peers as benchmark subjects (one row each: VV, VF, FF, EF and curve sweeps). `in`
// must outlive them.
std::unique_ptr<Subject> openmesh_subject(const PeerInput &in);
std::unique_ptr<Subject> cgal_subject(const PeerInput &in);

// What both peers do the same way, over a small adapter per library. An adapter P gives,
// for its mesh type P::Mesh and half-edge handle P::H: P::build(in, m, b, face_input)
// (see add_triangles), P::halfedges(m) (a range), P::index(h), P::border(m, h) (no face),
// P::source(m, h) (a vertex id), P::next(m, h) and P::n_halfedges(m); for the benchmark,
// the circulations of peer_row.

// Offers the triangles of `in` to a peer: degenerate ones are skipped and counted, refused
// ones counted (with a few examples). `add(c)` adds the triangle with corners c[0..2] and
// says whether the peer took it; `face_input`, when given, gets the submitted index of
// each face taken, in the peer's face order.
template <class Add>
void add_triangles(const PeerInput &in, PeerBuild &b, std::vector<uint32_t> *face_input, Add add) {
  for (size_t t = 0; t < in.n_triangles; ++t) {
    const uint32_t *c = in.triangles + 3 * t;
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) {
      b.skipped_degenerate++;
      continue;
    }
    b.submitted++;
    if (!add(c)) {
      if (b.refused_examples.size() < 8) b.refused_examples.push_back(uint32_t(t));
      b.refused++;
    } else if (face_input) {
      face_input->push_back(uint32_t(t));
    }
  }
}

// The boundary loops (face-less half-edges, which run against topomesh's curves: each loop
// is reversed) as vertex ids, into a.curves.
template <class P> void boundary_loops(const typename P::Mesh &m, size_t n_halfedges, Answers &a) {
  a.have_curves = true;
  std::vector<uint8_t> seen(n_halfedges, 0);
  for (auto h : P::halfedges(m)) {
    if (!P::border(m, h) || seen[P::index(h)]) continue;
    std::vector<uint32_t> loop;
    typename P::H g = h;
    do {
      seen[P::index(g)] = 1;
      loop.push_back(P::source(m, g));
      g = P::next(m, g);
    } while (g != h && loop.size() <= n_halfedges);
    std::reverse(loop.begin(), loop.end());
    a.curves.push_back(loop);
  }
}

// The curves sweep of the benchmark: every boundary loop walked once; a checksum of the
// source vertices, n counting the steps.
template <class P> uint64_t curve_sweep(const typename P::Mesh &m, size_t n_halfedges, uint64_t &n) {
  uint64_t cs = 0;
  std::vector<bool> seen(n_halfedges, false);
  for (auto h : P::halfedges(m)) {
    if (seen[P::index(h)] || !P::border(m, h)) continue;
    typename P::H g = h;
    do {
      seen[P::index(g)] = true;
      cs += uint64_t(P::source(m, g)) + 1;
      ++n;
      g = P::next(m, g);
    } while (g != h);
  }
  return cs;
}

// The benchmark row of a peer: the VV, VF, FF and EF sweeps over its adapter's circulations
// (P::each_vv, P::each_vf, P::each_ff call f(element id, neighbour id) at every step that
// meets a vertex or a face; P::each_ef calls f(face id) for each face of each edge), with
// checksums of the ids met, and the curves sweep. `m` holds the subject's current mesh.
template <class P> LibBench peer_row(const char *lib, const std::unique_ptr<typename P::Mesh> &m) {
  LibBench r;
  r.lib = lib;
  r.owns_build = true;
  r.sweeps.push_back(sweep("VV", [&m](uint64_t &n) {
    uint64_t cs = 0;
    P::each_vv(*m, [&](uint64_t v, uint64_t w) { cs += w * (v + 1), ++n; });
    return cs;
  }));
  r.sweeps.push_back(sweep("VF", [&m](uint64_t &n) {
    uint64_t cs = 0;
    P::each_vf(*m, [&](uint64_t v, uint64_t f) { cs += (f + 1) * (v + 1), ++n; });
    return cs;
  }));
  r.sweeps.push_back(sweep("FF", [&m](uint64_t &n) {
    uint64_t cs = 0;
    P::each_ff(*m, [&](uint64_t f, uint64_t g) { cs += (g + 1) * (f + 1), ++n; });
    return cs;
  }));
  r.sweeps.push_back(sweep("EF", [&m](uint64_t &n) {
    uint64_t cs = 0;
    P::each_ef(*m, [&](uint64_t f) { cs += f + 1, ++n; });
    return cs;
  }));
  r.sweeps.push_back(
      sweep("curves", [&m](uint64_t &n) { return curve_sweep<P>(*m, P::n_halfedges(*m), n); }));
  return r;
}

// What the benchmark subjects of both peers share: the input, the current build and its
// counts. Each peer adds describe() and rows().
template <class P> class PeerSubject : public Subject {
public:
  explicit PeerSubject(const PeerInput &in) : in_(in) {}
  void release() override { m_.reset(); }
  void build() override {
    m_ = std::make_unique<typename P::Mesh>();
    b_ = PeerBuild();
    P::build(in_, *m_, b_, nullptr);
  }

protected:
  const PeerInput &in_;
  std::unique_ptr<typename P::Mesh> m_;
  PeerBuild b_;
};

} // namespace diffmesh
