// A small OFF reader shared by the differential tests, the benchmark and subdivide, so that
// OpenMesh, CGAL and topomesh are all built from the SAME arrays.
//
// Accepts OFF, COFF, NOFF, CNOFF, STOFF headers (counts on the header line or the next),
// '#' comments and blank lines, extra numbers after a vertex's x y z (colours, normals,
// texture coordinates) and after a face's indices (face colours). A polygon with n > 3
// corners is fan-triangulated from its first corner: (c0, ci, ci+1). Degenerate triangles
// (a repeated vertex id) are kept in the arrays and counted; the caller decides.
#pragma once

#include "../diff_common/text.hpp"

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace diffmesh {

struct Soup : difftext::Points {
  std::vector<uint32_t> triangles; // 3 per triangle, after fan triangulation
  size_t n_faces = 0;              // faces in the file
  std::map<int, size_t> face_sizes; // corners -> how many faces
  size_t degenerate = 0;           // triangles with a repeated vertex id
  std::string header;              // OFF, COFF, ...
  bool face_extras = false;        // numbers after some face's indices (colours)
  bool vertex_extras = false;      // numbers after some vertex's x y z

  size_t n_triangles() const { return triangles.size() / 3; }
  bool is_degenerate(size_t t) const {
    const uint32_t *c = &triangles[3 * t];
    return c[0] == c[1] || c[1] == c[2] || c[2] == c[0];
  }
};

namespace detail {
using difftext::Lines;
using difftext::num;
using difftext::skip_ws;
} // namespace detail

// Reads `path` into `s`; on failure returns false with a message in `err`.
inline bool read_off(const std::string &path, Soup &s, std::string &err) {
  std::string text;
  if (!difftext::slurp(path, text)) { err = "cannot read " + path; return false; }
  s = Soup();
  s.name = difftext::file_name(path);
  if (s.name.size() > 4 && s.name.compare(s.name.size() - 4, 4, ".off") == 0)
    s.name.resize(s.name.size() - 4);

  detail::Lines lines{text.data(), text.data() + text.size()};
  const char *b, *e;
  auto fail = [&](const std::string &m) { err = path + ": " + m; return false; };
  if (!lines.next(b, e)) return fail("empty file");
  const char *h = b;
  while (b < e && *b != ' ' && *b != '\t') ++b;
  s.header.assign(h, b);
  if (s.header.size() < 3 || s.header.compare(s.header.size() - 3, 3, "OFF") != 0 ||
      s.header.find('4') != std::string::npos || s.header.find('n') != std::string::npos)
    return fail("unsupported header '" + s.header + "'");
  detail::skip_ws(b, e);
  if (b == e && !lines.next(b, e)) return fail("no counts");
  size_t nv = 0, nf = 0;
  if (!detail::num(b, e, nv) || !detail::num(b, e, nf)) return fail("bad counts line");
  s.n_vertices = nv;
  s.n_faces = nf;
  s.positions.resize(3 * nv);
  for (size_t v = 0; v < nv; ++v) {
    if (!lines.next(b, e)) return fail("file ends in vertex " + std::to_string(v));
    for (int k = 0; k < 3; ++k)
      if (!detail::num(b, e, s.positions[3 * v + k]))
        return fail("bad coordinate in vertex " + std::to_string(v));
    detail::skip_ws(b, e);
    if (b != e) s.vertex_extras = true;
  }
  s.triangles.reserve(3 * nf);
  std::vector<uint32_t> poly;
  for (size_t i = 0; i < nf; ++i) {
    if (!lines.next(b, e)) return fail("file ends in face " + std::to_string(i));
    int n = 0;
    if (!detail::num(b, e, n) || n < 1) return fail("bad corner count in face " + std::to_string(i));
    poly.resize(size_t(n));
    for (int k = 0; k < n; ++k) {
      // Some writers put a face on several lines.
      detail::skip_ws(b, e);
      if (b == e && !lines.next(b, e)) return fail("file ends in face " + std::to_string(i));
      if (!detail::num(b, e, poly[k]) || poly[k] >= nv)
        return fail("bad vertex id in face " + std::to_string(i));
    }
    detail::skip_ws(b, e);
    if (b != e) s.face_extras = true;
    s.face_sizes[n]++;
    for (int k = 1; k + 1 < n; ++k) {
      s.triangles.insert(s.triangles.end(), {poly[0], poly[k], poly[k + 1]});
      if (s.is_degenerate(s.n_triangles() - 1)) s.degenerate++;
    }
  }
  return true;
}

// A benchmark's mesh: read, then `tool: name (N triangles)` on stderr; false, with
// `tool: reason` on stderr, when it cannot be read.
inline bool read_bench_mesh(const char *tool, const std::string &path, Soup &s) {
  std::string err;
  if (!read_off(path, s, err)) {
    std::fprintf(stderr, "%s: %s\n", tool, err.c_str());
    return false;
  }
  std::fprintf(stderr, "%s: %s (%zu triangles)\n", tool, s.name.c_str(), s.n_triangles());
  return true;
}

} // namespace diffmesh
