// topomesh's answers through its C API, plus the self-consistency checks that need no peer.
#pragma once

#include "answers.hpp"

#include <topomesh/topomesh.h>

#include <cstdio>
#include <string>
#include <vector>

namespace diffmesh {

// Collects failures with a cap on how many get printed per kind.
struct Checker {
  std::string context; // "mesh L2 input"
  size_t failures = 0;
  std::vector<std::pair<std::string, size_t>> per_kind;
  void fail(const std::string &kind, const std::string &detail) {
    ++failures;
    size_t *n = nullptr;
    for (auto &p : per_kind)
      if (p.first == kind) n = &p.second;
    if (!n) {
      per_kind.push_back({kind, 0});
      n = &per_kind.back().second;
    }
    if (++*n <= 8) std::printf("MISMATCH [%s] %s: %s\n", context.c_str(), kind.c_str(), detail.c_str());
    else if (*n == 9) std::printf("MISMATCH [%s] %s: (more not shown)\n", context.c_str(), kind.c_str());
  }
};

// Checks `cond`; the kind and detail strings are only built on failure.
#define DIFF_CHECK(chk, cond, kind, detail)                                                        \
  do {                                                                                             \
    if (!(cond)) (chk).fail((kind), (detail));                                                     \
  } while (0)

std::string str(const std::vector<uint32_t> &v);
std::string str(const std::vector<Pair> &v);
std::string str(const Pair &p);

// One relation call into a growing buffer; returns false (and reports) on an error status.
using RelationFn = topomesh_status (*)(const che_mesh *, uint32_t, uint32_t *, size_t, size_t *);
bool relation(RelationFn f, const che_mesh *m, uint32_t id, std::vector<uint32_t> &out);
std::string last_error();

// Which elements to ask about: every one, or a stride (level 1 answers vertex and edge
// queries by scanning, O(T) each).
struct Sampling {
  size_t vertex_stride = 1, edge_stride = 1, face_stride = 1;
  bool curves = true;
};

// Maps the structure's ids to common ids: vmap[v] (structure vertex -> common vertex),
// fmap[t] (structure triangle -> common face), with `n_common_faces` faces in the common
// numbering. Runs the self-consistency checks on the way.
Answers topomesh_answers(const che_mesh *m, const std::vector<uint32_t> &vmap,
                         const std::vector<uint32_t> &fmap, size_t n_common_faces,
                         const Sampling &s, Checker &chk);

// Checks the zero-copy views against the relation calls and the CHE invariants.
void check_views(const che_mesh *m, Checker &chk);

} // namespace diffmesh
