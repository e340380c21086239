// Head-to-head benchmark: topomesh (levels 1-3; C API per element, star iterator, CSR bulk
// calls, C++ wrapper, zero-copy arrays) against OpenMesh and CGAL Surface_mesh, in one
// process, from the same arrays, REPS repetitions, medians.
//
//   topomesh_bench [--reps N] [--md FILE] MESH.off...
//
// Per mesh: build time from the arrays (positions included everywhere), connectivity memory
// from container sizes and the resident-set growth over one build, and full sweeps of VV,
// VF, FF, EF and the boundary curves. Every sweep folds what it visits into a checksum
// (printed; equal across libraries when every face was accepted) so nothing is optimised
// away. Markdown tables go to stdout and, with --md, to FILE.
#include "off_reader.hpp"
#include "peers.hpp"

#include <topomesh/topomesh.h>
#include <topomesh/topomesh.hpp>

#include <cmath>
#include <cstdarg>
#include <cstring>
#include <map>

using namespace diffmesh;

namespace {

// The zero-copy walks use the header's inline arithmetic.
inline uint32_t nxt(uint32_t h) { return che_next(h); }
inline uint32_t prv(uint32_t h) { return che_prev(h); }

struct Out {
  std::string md;
  FILE *file = nullptr;
  void operator()(const char *fmt, ...) __attribute__((format(printf, 2, 3))) {
    char buf[4096];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    std::fputs(buf, stdout);
    std::fflush(stdout);
    if (file) std::fputs(buf, file);
  }
};

// Per-element C calls into a fixed buffer (a vertex degree above 256 falls back to a
// vector).
template <class F> uint64_t each_answer(F f, const che_mesh *m, uint32_t id, uint32_t *buf, size_t cap,
                                        std::vector<uint32_t> &big, const uint32_t *&out, size_t &len) {
  topomesh_status s = f(m, id, buf, cap, &len);
  out = buf;
  if (s == TOPOMESH_STATUS_BUFFER_TOO_SMALL) {
    big.resize(len);
    s = f(m, id, big.data(), big.size(), &len);
    out = big.data();
  }
  if (s != TOPOMESH_STATUS_OK) {
    std::fprintf(stderr, "bench: relation call failed on %u: %s\n", id, topomesh_status_str(s));
    std::exit(1);
  }
  return len;
}

// Estimated seconds of a sweep that costs `per` scans of all half-edges per element (about
// 1 ns per half-edge scanned, measured on bunny00 at level 1).
double scan_seconds(size_t elements, size_t nt, double per) { return double(elements) * per * 3.0 * nt * 1e-9; }
constexpr double kMaxSweepSeconds = 2;

// The header-only C++ wrapper (topomesh.hpp): star ranges over the C stack iterator,
// fixed-size relations into std::array / SmallIds, curves into a std::vector.
LibBench cpp_row(che_mesh *m, uint32_t level, int reps, const LibBench &base) {
  LibBench r = base;
  r.path = "C++ wrapper";
  r.build_ms.clear();
  // Borrow the handle: the Surface must not free it.
  topomesh::Surface surf(m);
  struct Release {
    topomesh::Surface &s;
    ~Release() { s.release(); }
  } release{surf};
  using namespace topomesh;
  const uint32_t nv = uint32_t(surf.num_vertices()), nt = uint32_t(surf.num_triangles()),
                 ne = uint32_t(surf.num_edges());
  const std::string slow = "O(T) per query at level 1";
  bool vslow = level < 2 && scan_seconds(nv, nt, 1) > kMaxSweepSeconds;
  r.sweeps.push_back(vslow ? skipped_sweep("VV", slow) : time_sweep("VV", reps, [&](uint64_t &n) {
    uint64_t cs = 0;
    for (uint32_t v = 0; v < nv; ++v)
      for (VertexId w : surf.vertices_around(VertexId{v})) cs += uint64_t(w.value()) * (v + 1), ++n;
    return cs;
  }));
  r.sweeps.push_back(vslow ? skipped_sweep("VF", slow) : time_sweep("VF", reps, [&](uint64_t &n) {
    uint64_t cs = 0;
    for (uint32_t v = 0; v < nv; ++v)
      for (TriangleId t : surf.triangles_around(VertexId{v})) cs += uint64_t(t.value() + 1) * (v + 1), ++n;
    return cs;
  }));
  r.sweeps.push_back(time_sweep("FF", reps, [&](uint64_t &n) {
    uint64_t cs = 0;
    for (uint32_t t = 0; t < nt; ++t)
      for (TriangleId g : surf.triangle_triangles(TriangleId{t}))
        if (g.valid()) cs += uint64_t(g.value() + 1) * (t + 1), ++n;
    return cs;
  }));
  bool eslow = level < 2 && scan_seconds(ne, nt, 1) > kMaxSweepSeconds;
  r.sweeps.push_back(eslow ? skipped_sweep("EF", slow) : time_sweep("EF", reps, [&](uint64_t &n) {
    uint64_t cs = 0;
    for (uint32_t e = 0; e < ne; ++e)
      for (TriangleId t : surf.edge_triangles(EdgeId{e})) cs += t.value() + 1, ++n;
    return cs;
  }));
  const size_t nb = size_t(surf.summary().boundary_edges), nc = surf.num_boundary_curves();
  bool cslow = (level < 2 && scan_seconds(nb, nt, 1) > kMaxSweepSeconds) ||
               (level < 3 && scan_seconds(nc, nt, 1) > kMaxSweepSeconds);
  r.sweeps.push_back(cslow ? skipped_sweep("curves", "O(T) per curve below level 3")
                           : time_sweep("curves", reps, [&](uint64_t &n) {
                               uint64_t cs = 0;
                               for (uint32_t c = 0; c < nc; ++c)
                                 for (VertexId v : surf.boundary_curve_vertices(c)) cs += v.value() + 1, ++n;
                               return cs;
                             }));
  return r;
}

void topomesh_rows(const Soup &s, uint32_t level, int reps, std::vector<LibBench> &rows) {
  const size_t nt_in = s.n_triangles();
  LibBench base;
  base.lib = "topomesh L" + std::to_string(level);
  che_mesh *m = nullptr;
  for (int k = 0; k < reps; ++k) {
    double t0 = now_ms();
    che_mesh *x = nullptr;
    if (che_mesh_from_triangles(s.triangles.data(), nt_in, s.n_vertices, s.positions.data(), level, &x) !=
        TOPOMESH_STATUS_OK) {
      std::fprintf(stderr, "bench: build failed\n");
      std::exit(1);
    }
    base.build_ms.push_back(now_ms() - t0);
    che_mesh_free(x);
  }
  long before = rss_bytes();
  che_mesh_from_triangles(s.triangles.data(), nt_in, s.n_vertices, s.positions.data(), level, &m);
  base.rss_delta = rss_bytes() - before;
  che_memory mem;
  std::memset(&mem, 0, sizeof mem);
  che_mesh_memory(m, &mem);
  base.connectivity_bytes = size_t(mem.topology);
  const size_t nv = che_mesh_num_vertices(m), nt = che_mesh_num_triangles(m), ne = che_mesh_num_edges(m);
  base.faces = nt;
  base.vertices = nv;
  {
    che_summary sum;
    std::memset(&sum, 0, sizeof sum);
    che_mesh_summary(m, &sum);
    base.note = std::to_string(sum.flipped_triangles) + " flipped, " + std::to_string(sum.split_vertices) +
                " vertices split, " + std::to_string(sum.non_manifold_edges) + " non-manifold edges, " +
                std::to_string(sum.dropped_degenerate) + " degenerate dropped";
  }
  const std::string slow = "O(T) per query at level 1";

  // --- C API, one call per element.
  LibBench c = base;
  c.path = "C API";
  {
    uint32_t buf[256];
    std::vector<uint32_t> big;
    const uint32_t *a;
    size_t len;
    bool vslow = level < 2 && scan_seconds(nv, nt, 1) > kMaxSweepSeconds;
    c.sweeps.push_back(vslow ? skipped_sweep("VV", slow) : time_sweep("VV", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      for (uint32_t v = 0; v < nv; ++v) {
        n += each_answer(che_vertex_vertices, m, v, buf, 256, big, a, len);
        for (size_t i = 0; i < len; ++i) cs += uint64_t(a[i]) * (v + 1);
      }
      return cs;
    }));
    c.sweeps.push_back(vslow ? skipped_sweep("VF", slow) : time_sweep("VF", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      for (uint32_t v = 0; v < nv; ++v) {
        n += each_answer(che_vertex_triangles, m, v, buf, 256, big, a, len);
        for (size_t i = 0; i < len; ++i) cs += uint64_t(a[i] + 1) * (v + 1);
      }
      return cs;
    }));
    c.sweeps.push_back(time_sweep("FF", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      for (uint32_t t = 0; t < nt; ++t) {
        each_answer(che_triangle_triangles, m, t, buf, 256, big, a, len);
        for (size_t i = 0; i < 3; ++i)
          if (a[i] != TOPOMESH_NONE) cs += uint64_t(a[i] + 1) * (t + 1), ++n;
      }
      return cs;
    }));
    bool eslow = level < 2 && scan_seconds(ne, nt, 1) > kMaxSweepSeconds;
    c.sweeps.push_back(eslow ? skipped_sweep("EF", slow) : time_sweep("EF", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      for (uint32_t e = 0; e < ne; ++e) {
        n += each_answer(che_edge_triangles, m, e, buf, 256, big, a, len);
        for (size_t i = 0; i < len; ++i) cs += uint64_t(a[i] + 1);
      }
      return cs;
    }));
    size_t nb = 0;
    {
      che_summary sum;
      che_mesh_summary(m, &sum);
      nb = size_t(sum.boundary_edges);
    }
    size_t nc = che_mesh_num_boundary_curves(m);
    bool cslow = (level < 2 && scan_seconds(nb, nt, 1) > kMaxSweepSeconds) ||
                 (level < 3 && scan_seconds(nc, nt, 1) > kMaxSweepSeconds);
    c.sweeps.push_back(cslow ? skipped_sweep("curves", "O(T) per curve below level 3")
                             : time_sweep("curves", reps, [&](uint64_t &n) {
                                 uint64_t cs = 0;
                                 size_t k = che_mesh_num_boundary_curves(m);
                                 for (uint32_t cv = 0; cv < k; ++cv) {
                                   n += each_answer(che_boundary_curve_vertices, m, cv, buf, 256, big, a, len);
                                   for (size_t i = 0; i < len; ++i) cs += a[i] + 1;
                                 }
                                 return cs;
                               }));
  }
  rows.push_back(c);

  // --- The star iterator on the caller's stack.
  LibBench st = base;
  st.path = "star iterator";
  st.build_ms.clear();
  {
    bool vslow = level < 2 && scan_seconds(nv, nt, 2) > kMaxSweepSeconds;
    st.sweeps.push_back(vslow ? skipped_sweep("VV", slow) : time_sweep("VV", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      che_star_iter it;
      che_star_step step;
      for (uint32_t v = 0; v < nv; ++v) {
        che_star_begin(m, v, &it);
        while (che_star_next(&it, &step)) cs += uint64_t(step.vertex) * (v + 1), ++n;
      }
      return cs;
    }));
    st.sweeps.push_back(vslow ? skipped_sweep("VF", slow) : time_sweep("VF", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      che_star_iter it;
      che_star_step step;
      for (uint32_t v = 0; v < nv; ++v) {
        che_star_begin(m, v, &it);
        while (che_star_next(&it, &step))
          if (step.triangle != TOPOMESH_NONE) cs += uint64_t(step.triangle + 1) * (v + 1), ++n;
      }
      return cs;
    }));
  }
  rows.push_back(st);

  // --- CSR bulk calls (one call for all vertices; the buffers are sized outside the timing).
  LibBench csr = base;
  csr.path = "CSR bulk";
  csr.build_ms.clear();
  {
    using CsrFn = topomesh_status (*)(const che_mesh *, uint32_t *, size_t, uint32_t *, size_t, size_t *, size_t *);
    auto run = [&](const char *name, CsrFn f, uint64_t add, bool skip_none) {
      size_t no = 0, ni = 0;
      f(m, nullptr, 0, nullptr, 0, &no, &ni);
      std::vector<uint32_t> off(no), idx(ni);
      csr.sweeps.push_back(time_sweep(name, reps, [&](uint64_t &n) {
        size_t a = 0, b = 0;
        if (f(m, off.data(), off.size(), idx.data(), idx.size(), &a, &b) != TOPOMESH_STATUS_OK) {
          std::fprintf(stderr, "bench: CSR call failed\n");
          std::exit(1);
        }
        uint64_t cs = 0;
        size_t rows_n = a ? a - 1 : 0;
        for (size_t r = 0; r < rows_n; ++r)
          for (uint32_t k = off[r]; k < off[r + 1]; ++k) {
            uint32_t x = idx[k];
            if (skip_none && x == TOPOMESH_NONE) continue;
            cs += (uint64_t(x) + add) * (r + 1);
            ++n;
          }
        return cs;
      }));
    };
    run("VV", che_mesh_vertex_vertices_csr, 0, false);
    run("VF", che_mesh_vertex_triangles_csr, 1, false);
    run("FF", che_mesh_triangle_triangles_csr, 1, true);
  }
  rows.push_back(csr);

  rows.push_back(cpp_row(m, level, reps, base));

  // --- Zero-copy: the arrays themselves, with inline next/prev.
  LibBench z = base;
  z.path = "zero-copy";
  z.build_ms.clear();
  {
    size_t len = 0;
    const uint32_t *V = che_mesh_half_edge_vertices(m, &len);
    const uint32_t *O = che_mesh_opposites(m, &len);
    const uint32_t *VH = che_mesh_vertex_half_edges(m, &len);
    const uint32_t *CH = che_mesh_curve_half_edges(m, &len);
    const size_t nh = 3 * nt, nc = CH ? len : 0;
    if (VH) {
      z.sweeps.push_back(time_sweep("VV", reps, [&](uint64_t &n) {
        uint64_t cs = 0;
        for (uint32_t v = 0; v < nv; ++v) {
          uint32_t h = VH[v], s0 = h;
          if (h == TOPOMESH_NONE) continue;
          do {
            cs += uint64_t(V[nxt(h)]) * (v + 1), ++n;
            uint32_t p = prv(h), g = O[p];
            if (g == TOPOMESH_NONE) {
              cs += uint64_t(V[p]) * (v + 1), ++n;
              break;
            }
            h = g;
          } while (h != s0);
        }
        return cs;
      }));
      z.sweeps.push_back(time_sweep("VF", reps, [&](uint64_t &n) {
        uint64_t cs = 0;
        for (uint32_t v = 0; v < nv; ++v) {
          uint32_t h = VH[v], s0 = h;
          if (h == TOPOMESH_NONE) continue;
          do {
            cs += uint64_t(h / 3 + 1) * (v + 1), ++n;
            h = O[prv(h)];
          } while (h != TOPOMESH_NONE && h != s0);
        }
        return cs;
      }));
    } else {
      z.sweeps.push_back(skipped_sweep("VV", "needs VH (level 2)"));
      z.sweeps.push_back(skipped_sweep("VF", "needs VH (level 2)"));
    }
    z.sweeps.push_back(time_sweep("FF", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      for (uint32_t h = 0; h < nh; ++h)
        if (O[h] != TOPOMESH_NONE) cs += uint64_t(O[h] / 3 + 1) * (h / 3 + 1), ++n;
      return cs;
    }));
    z.sweeps.push_back(time_sweep("EF", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      for (uint32_t h = 0; h < nh; ++h) {
        uint32_t g = O[h];
        if (g == TOPOMESH_NONE) cs += h / 3 + 1, ++n;
        else if (h < g) cs += h / 3 + 1 + g / 3 + 1, n += 2;
      }
      return cs;
    }));
    z.sweeps.push_back(time_sweep("curves", reps, [&](uint64_t &n) {
      uint64_t cs = 0;
      auto next_boundary = [&](uint32_t h) {
        if (VH) return VH[V[nxt(h)]];
        uint32_t g = nxt(h); // level 1: rotate clockwise around the target to the boundary
        while (O[g] != TOPOMESH_NONE) g = nxt(O[g]);
        return g;
      };
      if (CH) {
        for (size_t c = 0; c < nc; ++c) {
          uint32_t h = CH[c];
          do cs += V[h] + 1, ++n, h = next_boundary(h);
          while (h != CH[c]);
        }
      } else {
        std::vector<bool> seen(nh, false);
        for (uint32_t h0 = 0; h0 < nh; ++h0) {
          if (O[h0] != TOPOMESH_NONE || seen[h0]) continue;
          uint32_t h = h0;
          do seen[h] = true, cs += V[h] + 1, ++n, h = next_boundary(h);
          while (h != h0);
        }
      }
      return cs;
    }));
  }
  rows.push_back(z);
  che_mesh_free(m);
}

std::string fmt_ms(double ms) {
  char b[32];
  if (ms < 0) return "–";
  if (ms < 10) std::snprintf(b, sizeof b, "%.2f", ms);
  else if (ms < 100) std::snprintf(b, sizeof b, "%.1f", ms);
  else std::snprintf(b, sizeof b, "%.0f", ms);
  return b;
}
std::string fmt_mb(double bytes) {
  char b[32];
  if (bytes < 0) return "–";
  std::snprintf(b, sizeof b, "%.1f", bytes / 1048576.0);
  return b;
}
std::string fmt_ratio(double num, double den) {
  char b[32];
  if (num <= 0 || den <= 0) return "–";
  std::snprintf(b, sizeof b, "%.1f×", num / den);
  return b;
}

const char *kSweeps[] = {"VV", "VF", "FF", "EF", "curves"};

// The median time of a sweep; -1 when skipped or when it visited nothing (no boundary).
double sweep_ms(const LibBench &r, const char *name) {
  for (auto &s : r.sweeps)
    if (s.name == name && !s.skipped() && s.count > 0) return median(s.ms);
  return -1;
}

void report(Out &out, const Soup &s, std::vector<LibBench> &rows, int reps) {
  out("\n### %s\n\n", s.name.c_str());
  out("%zu vertices, %zu triangles. Medians of %d runs, milliseconds; memory in MiB.\n\n", s.n_vertices,
      s.n_triangles(), reps);
  out("| library | path | build | connectivity | RSS growth | VV | VF | FF | EF | curves |\n");
  out("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (auto &r : rows) {
    bool first_of_build = !r.build_ms.empty();
    out("| %s | %s | %s | %s | %s |", r.lib.c_str(), r.path.empty() ? "" : r.path.c_str(),
        first_of_build ? fmt_ms(median(r.build_ms)).c_str() : "″",
        first_of_build ? fmt_mb(double(r.connectivity_bytes)).c_str() : "″",
        first_of_build ? fmt_mb(double(r.rss_delta)).c_str() : "″");
    for (const char *n : kSweeps) out(" %s |", fmt_ms(sweep_ms(r, n)).c_str());
    out("\n");
  }
  const LibBench &om = rows[0], &cg = rows[1];
  out("\nRatios (OpenMesh ÷ topomesh / CGAL ÷ topomesh; above 1 means topomesh is faster or smaller):\n\n");
  out("| topomesh | path | build | connectivity | VV | VF | FF | EF | curves |\n");
  out("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  const LibBench *build_row = nullptr;
  for (size_t i = 2; i < rows.size(); ++i) {
    const LibBench &r = rows[i];
    if (!r.build_ms.empty()) build_row = &r;
    auto both = [&](double a, double b, double t) { return fmt_ratio(a, t) + " / " + fmt_ratio(b, t); };
    std::string b = r.build_ms.empty() ? "″"
                                       : both(median(om.build_ms), median(cg.build_ms), median(r.build_ms));
    std::string mem = r.build_ms.empty() ? "″"
                                         : both(double(om.connectivity_bytes), double(cg.connectivity_bytes),
                                                double(build_row->connectivity_bytes));
    out("| %s | %s | %s | %s |", r.lib.c_str(), r.path.c_str(), b.c_str(), mem.c_str());
    for (const char *n : kSweeps) out(" %s |", both(sweep_ms(om, n), sweep_ms(cg, n), sweep_ms(r, n)).c_str());
    out("\n");
  }
  // Checksums: every topomesh row must agree with the others; with the peers too when they
  // kept every face (otherwise they walk a different mesh).
  const bool peers_full = om.faces == s.n_triangles() && cg.faces == s.n_triangles();
  const bool same_mesh = peers_full && rows[2].vertices == s.n_vertices;
  std::map<std::string, uint64_t> ref;
  for (size_t i = rows.size(); i-- > 2;)
    for (auto &sw : rows[i].sweeps)
      if (!sw.skipped()) ref[sw.name] = sw.checksum; // ends at the first row that ran it
  std::string diffs, skips;
  for (size_t i = 0; i < rows.size(); ++i) {
    const LibBench &r = rows[i];
    if (i < 2 && !same_mesh) continue;
    for (auto &sw : r.sweeps) {
      if (sw.skipped()) {
        skips += " " + r.lib + " " + r.path + " " + sw.name + " (" + sw.note + ");";
        continue;
      }
      if (ref.count(sw.name) && sw.checksum != ref[sw.name])
        diffs += " " + r.lib + (r.path.empty() ? "" : " " + r.path) + " " + sw.name + "=" +
                 std::to_string(sw.checksum) + ";";
    }
  }
  out("\nChecksums: VV %llu, VF %llu, FF %llu, EF %llu, curves %llu — %s%s\n", (unsigned long long)ref["VV"],
      (unsigned long long)ref["VF"], (unsigned long long)ref["FF"], (unsigned long long)ref["EF"],
      (unsigned long long)ref["curves"],
      !diffs.empty()  ? "DIFFER:"
      : same_mesh     ? "all libraries and paths agree"
      : !peers_full   ? "all topomesh paths agree (the peers refused faces: not comparable)"
                      : "all topomesh paths agree (topomesh split non-manifold vertices: ids differ from the peers')",
      diffs.c_str());
  if (!skips.empty()) out("Skipped:%s\n", skips.c_str());
  out("Faces kept: OpenMesh %zu, CGAL %zu, topomesh %zu (of %zu; %s).%s\n", om.faces, cg.faces,
      rows[2].faces, s.n_triangles(), rows[2].note.c_str(),
      peers_full ? "" : " The peers refused faces, so they sweep a smaller mesh: the ratios flatter them.");

  // The targets, on this mesh.
  auto find = [&](const std::string &lib, const std::string &path) -> const LibBench * {
    for (auto &r : rows)
      if (r.lib == lib && r.path == path) return &r;
    return nullptr;
  };
  const LibBench *l2 = find("topomesh L2", "C API"), *l1 = find("topomesh L1", "C API");
  double b2 = median(l2->build_ms), bo = median(om.build_ms), bc = median(cg.build_ms);
  out("\nTargets: level-2 build %s faster than OpenMesh, %s than CGAL (target 10×: %s); ",
      fmt_ratio(bo, b2).c_str(), fmt_ratio(bc, b2).c_str(), bo >= 10 * b2 && bc >= 10 * b2 ? "met" : "missed");
  double mo = double(l1->connectivity_bytes) / double(om.connectivity_bytes),
         mc = double(l1->connectivity_bytes) / double(cg.connectivity_bytes);
  out("level-1 connectivity %.2f of OpenMesh's, %.2f of CGAL's (target ≤ 0.50: %s)", mo, mc,
      mo <= 0.5 && mc <= 0.5 ? "met" : "missed");
  for (const char *n : {"VV", "VF", "FF"}) {
    double peer = std::min(sweep_ms(om, n), sweep_ms(cg, n));
    out("; %s vs the faster peer (target 1.5×):", n);
    for (const char *path : {"C API", "C++ wrapper", "zero-copy"}) {
      const LibBench *r = find("topomesh L2", path);
      double t = r ? sweep_ms(*r, n) : -1;
      out(" L2 %s %s%s", path, fmt_ratio(peer, t).c_str(), t > 0 && peer >= 1.5 * t ? " met" : t > 0 ? " missed" : "");
    }
  }
  out(".\n");
}

} // namespace

int main(int argc, char **argv) {
  int reps = 5;
  std::vector<std::string> files;
  Out out;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (a == "--md" && i + 1 < argc) {
      out.file = std::fopen(argv[++i], "w");
      if (!out.file) { std::perror(argv[i]); return 1; }
    } else files.push_back(a);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: topomesh_bench [--reps N] [--md FILE] MESH.off...\n");
    return 2;
  }
  for (auto &f : files) {
    Soup s;
    std::string err;
    if (!read_off(f, s, err)) {
      std::fprintf(stderr, "bench: %s\n", err.c_str());
      return 1;
    }
    std::fprintf(stderr, "bench: %s (%zu triangles)\n", s.name.c_str(), s.n_triangles());
    PeerInput in{s.n_vertices, s.positions.data(), s.triangles.data(), s.n_triangles()};
    std::vector<LibBench> rows;
    rows.push_back(openmesh_bench(in, reps));
    rows.push_back(cgal_bench(in, reps));
    for (uint32_t level = 1; level <= 3; ++level) topomesh_rows(s, level, reps, rows);
    report(out, s, rows, reps);
  }
  if (out.file) std::fclose(out.file);
  return 0;
}
