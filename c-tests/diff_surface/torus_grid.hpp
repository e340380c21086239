// The torus of topomesh's generator (`topomesh::generate::torus_of`, src/generate.rs) in
// C++: the same nu and nv, vertex order, positions and triangle order, so that the peers of
// the scale run (bench_scale.cpp) get the mesh `topomesh generate torus --triangles N`
// builds. A change there must come here too.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace diffmesh {

struct TorusGrid {
  uint64_t nu = 0, nv = 0;         // quads around the ring, around the tube
  std::vector<double> positions;   // 3 per vertex, vertex (i, j) at j * nu + i
  std::vector<uint32_t> triangles; // 3 per triangle, two per quad, quads row by row
  uint64_t n_vertices() const { return nu * nv; }
  uint64_t n_triangles() const { return 2 * nu * nv; }
};

// The grid torus_of(triangles) chooses, without allocating: false for a size of zero or
// past the 32-bit half-edge ids (as torus_of refuses).
inline bool torus_size(uint64_t triangles, TorusGrid &t) {
  const uint64_t most = (uint64_t(UINT32_MAX) - 1) / 3;
  if (triangles == 0 || triangles > most) return false;
  const uint64_t quads = std::max<uint64_t>((triangles + 1) / 2, 9);
  t.nv = std::max<uint64_t>(uint64_t(std::ceil(std::sqrt(double(quads) / 3.0))), 3);
  t.nu = std::max<uint64_t>((quads + t.nv - 1) / t.nv, 3);
  return 2 * t.nu * t.nv <= most;
}

// Fills the arrays of the grid torus_size chose (std::bad_alloc when memory runs out).
inline void torus_fill(TorusGrid &t) {
  const double tau = 2 * M_PI; // Rust's TAU, the same double
  const uint64_t nu = t.nu, nv = t.nv;
  t.positions.clear();
  t.positions.reserve(3 * nu * nv);
  for (uint64_t j = 0; j < nv; ++j)
    for (uint64_t i = 0; i < nu; ++i) {
      const double u = tau * double(i) / double(nu), v = tau * double(j) / double(nv);
      const double r = 2.0 + std::cos(v);
      t.positions.insert(t.positions.end(), {r * std::cos(u), r * std::sin(u), std::sin(v)});
    }
  auto id = [&](uint64_t i, uint64_t j) { return uint32_t((j % nv) * nu + (i % nu)); };
  t.triangles.clear();
  t.triangles.reserve(6 * nu * nv);
  for (uint64_t j = 0; j < nv; ++j)
    for (uint64_t i = 0; i < nu; ++i) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      t.triangles.insert(t.triangles.end(), {a, b, c, a, c, d});
    }
}

} // namespace diffmesh
