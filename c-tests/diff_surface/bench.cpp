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
// away. The repetitions are interleaved across libraries (see bench_util.hpp). Markdown
// tables go to stdout and, with --md, to FILE.
#include "off_reader.hpp"
#include "peers.hpp"

#include <topomesh/topomesh.h>
#include <topomesh/topomesh.hpp>

#include <cmath>
#include <cstring>
#include <map>

using namespace diffmesh;

namespace {

// The zero-copy walks use the header's inline arithmetic.
inline uint32_t nxt(uint32_t h) { return che_next(h); }
inline uint32_t prv(uint32_t h) { return che_prev(h); }

// One call per element into a fixed buffer (a longer answer falls back to a vector).
using RelFn = topomesh_status (*)(const che_mesh *, uint32_t, uint32_t *, size_t, size_t *);
struct Caller {
  uint32_t buf[256];
  std::vector<uint32_t> big;
  const uint32_t *out = nullptr;
  size_t len = 0;
  size_t operator()(RelFn f, const che_mesh *m, uint32_t id) {
    topomesh_status s = f(m, id, buf, 256, &len);
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
};

// Estimated seconds of a sweep that costs `per` scans of all half-edges per element, at the
// 1e-9 s per half-edge scanned this estimate assumes.
double scan_seconds(size_t elements, size_t nt, double per) { return double(elements) * per * 3.0 * nt * 1e-9; }
constexpr double kMaxSweepSeconds = 2;

// topomesh at one level; rows for each access path.
class TmSubject : public Subject {
public:
  TmSubject(const Soup &s, uint32_t level) : s_(s), level_(level) {}
  ~TmSubject() override { release(); }
  void release() override {
    che_mesh_free(m_);
    m_ = nullptr;
  }
  // On one thread, as the peers (and so that the benchmark thread's CPU time is all of it).
  void build() override {
    che_build_options o = che_build_options_default();
    o.level = level_;
    o.threads = 1;
    if (che_mesh_from_triangles_ex(s_.triangles.data(), s_.n_triangles(), s_.n_vertices, s_.positions.data(), &o,
                                   &m_) != TOPOMESH_STATUS_OK) {
      std::fprintf(stderr, "bench: topomesh build failed\n");
      std::exit(1);
    }
  }
  void describe(LibBench &r) const override {
    che_memory mem;
    std::memset(&mem, 0, sizeof mem);
    che_mesh_memory(m_, &mem);
    r.connectivity_bytes = size_t(mem.topology);
    r.faces = che_mesh_num_triangles(m_);
    r.vertices = che_mesh_num_vertices(m_);
    che_summary sum;
    std::memset(&sum, 0, sizeof sum);
    che_mesh_summary(m_, &sum);
    r.note = std::to_string(sum.flipped_triangles) + " flipped, " + std::to_string(sum.split_vertices) +
             " vertices split, " + std::to_string(sum.non_manifold_edges) + " non-manifold edges, " +
             std::to_string(sum.dropped_degenerate) + " degenerate dropped";
  }
  std::vector<LibBench> rows() override {
    // Sizes that decide which level-1 sweeps are too slow to run (O(T) per query).
    nv_ = che_mesh_num_vertices(m_);
    nt_ = che_mesh_num_triangles(m_);
    ne_ = che_mesh_num_edges(m_);
    che_summary sum;
    std::memset(&sum, 0, sizeof sum);
    che_mesh_summary(m_, &sum);
    nb_ = size_t(sum.boundary_edges);
    nc_ = che_mesh_num_boundary_curves(m_);
    return {c_api(), star(), csr(), cpp(), zero_copy()};
  }

private:
  const std::string slow_ = "O(T) per query at level 1";
  bool vslow(double per = 1) const { return level_ < 2 && scan_seconds(nv_, nt_, per) > kMaxSweepSeconds; }
  bool eslow() const { return level_ < 2 && scan_seconds(ne_, nt_, 1) > kMaxSweepSeconds; }
  bool cslow() const {
    return (level_ < 2 && scan_seconds(nb_, nt_, 1) > kMaxSweepSeconds) ||
           (level_ < 3 && scan_seconds(nc_, nt_, 1) > kMaxSweepSeconds);
  }
  LibBench row(const char *path, bool first = false) const {
    LibBench r;
    r.lib = "topomesh L" + std::to_string(level_);
    r.path = path;
    r.owns_build = first;
    return r;
  }

  LibBench c_api() {
    LibBench r = row("C API", true);
    r.sweeps.push_back(vslow() ? skipped_sweep("VV", slow_) : sweep("VV", [this](uint64_t &n) {
      Caller call;
      uint64_t cs = 0;
      for (uint32_t v = 0; v < nv_; ++v) {
        n += call(che_vertex_vertices, m_, v);
        for (size_t i = 0; i < call.len; ++i) cs += uint64_t(call.out[i]) * (v + 1);
      }
      return cs;
    }));
    r.sweeps.push_back(vslow() ? skipped_sweep("VF", slow_) : sweep("VF", [this](uint64_t &n) {
      Caller call;
      uint64_t cs = 0;
      for (uint32_t v = 0; v < nv_; ++v) {
        n += call(che_vertex_triangles, m_, v);
        for (size_t i = 0; i < call.len; ++i) cs += uint64_t(call.out[i] + 1) * (v + 1);
      }
      return cs;
    }));
    r.sweeps.push_back(sweep("FF", [this](uint64_t &n) {
      uint32_t ff[3];
      size_t len;
      uint64_t cs = 0;
      for (uint32_t t = 0; t < nt_; ++t) {
        che_triangle_triangles(m_, t, ff, 3, &len);
        for (size_t i = 0; i < 3; ++i)
          if (ff[i] != TOPOMESH_NONE) cs += uint64_t(ff[i] + 1) * (t + 1), ++n;
      }
      return cs;
    }));
    r.sweeps.push_back(eslow() ? skipped_sweep("EF", slow_) : sweep("EF", [this](uint64_t &n) {
      uint32_t ef[2];
      size_t len = 0;
      uint64_t cs = 0;
      for (uint32_t e = 0; e < ne_; ++e) {
        che_edge_triangles(m_, e, ef, 2, &len);
        for (size_t i = 0; i < len; ++i) cs += uint64_t(ef[i] + 1), ++n;
      }
      return cs;
    }));
    r.sweeps.push_back(cslow() ? skipped_sweep("curves", "O(T) per curve below level 3")
                               : sweep("curves", [this](uint64_t &n) {
                                   Caller call;
                                   uint64_t cs = 0;
                                   size_t k = che_mesh_num_boundary_curves(m_);
                                   for (uint32_t c = 0; c < k; ++c) {
                                     n += call(che_boundary_curve_vertices, m_, c);
                                     for (size_t i = 0; i < call.len; ++i) cs += call.out[i] + 1;
                                   }
                                   return cs;
                                 }));
    return r;
  }

  // A sweep of every vertex's star with the C star iterator: visit(step, v, checksum, n) at
  // every step.
  template <class Visit> Sweep star_sweep(const char *name, Visit visit) {
    if (vslow(2)) return skipped_sweep(name, slow_);
    return sweep(name, [this, visit](uint64_t &n) {
      uint64_t cs = 0;
      che_star_iter it;
      che_star_step step;
      for (uint32_t v = 0; v < nv_; ++v) {
        che_star_begin(m_, v, &it);
        while (che_star_next(&it, &step)) visit(step, v, cs, n);
      }
      return cs;
    });
  }

  LibBench star() {
    LibBench r = row("star iterator");
    r.sweeps.push_back(star_sweep("VV", [](const che_star_step &s, uint64_t v, uint64_t &cs, uint64_t &n) {
      cs += uint64_t(s.vertex) * (v + 1), ++n;
    }));
    r.sweeps.push_back(star_sweep("VF", [](const che_star_step &s, uint64_t v, uint64_t &cs, uint64_t &n) {
      if (s.triangle != TOPOMESH_NONE) cs += uint64_t(s.triangle + 1) * (v + 1), ++n;
    }));
    return r;
  }

  // One call for all rows; the buffers are sized (by a size query) outside the timing.
  LibBench csr() {
    LibBench r = row("CSR bulk");
    using CsrFn = topomesh_status (*)(const che_mesh *, uint32_t *, size_t, uint32_t *, size_t, size_t *, size_t *);
    auto add = [&](const char *name, CsrFn f, uint64_t plus, bool skip_none) {
      size_t no = 0, ni = 0;
      f(m_, nullptr, 0, nullptr, 0, &no, &ni);
      auto off = std::make_shared<std::vector<uint32_t>>(no), idx = std::make_shared<std::vector<uint32_t>>(ni);
      r.sweeps.push_back(sweep(name, [this, f, plus, skip_none, off, idx](uint64_t &n) {
        size_t a = 0, b = 0;
        if (f(m_, off->data(), off->size(), idx->data(), idx->size(), &a, &b) != TOPOMESH_STATUS_OK) {
          std::fprintf(stderr, "bench: CSR call failed\n");
          std::exit(1);
        }
        uint64_t cs = 0;
        for (size_t row = 0; row + 1 < a; ++row)
          for (uint32_t k = (*off)[row]; k < (*off)[row + 1]; ++k) {
            uint32_t x = (*idx)[k];
            if (skip_none && x == TOPOMESH_NONE) continue;
            cs += (uint64_t(x) + plus) * (row + 1), ++n;
          }
        return cs;
      }));
    };
    add("VV", che_mesh_vertex_vertices_csr, 0, false);
    add("VF", che_mesh_vertex_triangles_csr, 1, false);
    add("FF", che_mesh_triangle_triangles_csr, 1, true);
    return r;
  }

  // The header-only C++ wrapper (topomesh.hpp): from level 2 its vertex relations and
  // fixed-size ones step inline over the arrays the Surface keeps (FF from level 1);
  // otherwise they call the C API. It borrows the handle (released
  // before the Surface is destroyed).
  template <class F> auto with_surface(F &&f) {
    topomesh::Surface surf(m_);
    struct Release {
      topomesh::Surface &s;
      ~Release() { s.release(); }
    } release{surf};
    return f(static_cast<const topomesh::Surface &>(surf));
  }
  LibBench cpp() {
    using namespace topomesh;
    LibBench r = row("C++ wrapper");
    r.sweeps.push_back(vslow() ? skipped_sweep("VV", slow_) : sweep("VV", [this](uint64_t &n) {
      return with_surface([&](const Surface &s) {
        uint64_t cs = 0;
        for (uint32_t v = 0; v < nv_; ++v)
          for (VertexId w : s.vertex_vertices(VertexId{v})) cs += uint64_t(w.value()) * (v + 1), ++n;
        return cs;
      });
    }));
    r.sweeps.push_back(vslow() ? skipped_sweep("VF", slow_) : sweep("VF", [this](uint64_t &n) {
      return with_surface([&](const Surface &s) {
        uint64_t cs = 0;
        for (uint32_t v = 0; v < nv_; ++v)
          for (TriangleId t : s.vertex_triangles(VertexId{v})) cs += uint64_t(t.value() + 1) * (v + 1), ++n;
        return cs;
      });
    }));
    r.sweeps.push_back(sweep("FF", [this](uint64_t &n) {
      return with_surface([&](const Surface &s) {
        uint64_t cs = 0;
        for (uint32_t t = 0; t < nt_; ++t)
          for (TriangleId g : s.triangle_triangles(TriangleId{t}))
            if (g.valid()) cs += uint64_t(g.value() + 1) * (t + 1), ++n;
        return cs;
      });
    }));
    r.sweeps.push_back(eslow() ? skipped_sweep("EF", slow_) : sweep("EF", [this](uint64_t &n) {
      return with_surface([&](const Surface &s) {
        uint64_t cs = 0;
        for (uint32_t e = 0; e < ne_; ++e)
          for (TriangleId t : s.edge_triangles(EdgeId{e})) cs += t.value() + 1, ++n;
        return cs;
      });
    }));
    r.sweeps.push_back(cslow() ? skipped_sweep("curves", "O(T) per curve below level 3")
                               : sweep("curves", [this](uint64_t &n) {
                                   return with_surface([&](const Surface &s) {
                                     uint64_t cs = 0;
                                     for (uint32_t c = 0; c < nc_; ++c)
                                       for (VertexId v : s.boundary_curve_vertices(c)) cs += v.value() + 1, ++n;
                                     return cs;
                                   });
                                 }));
    return r;
  }

  // The arrays themselves, with inline next/prev (views fetched per sweep: a rebuild moves them).
  LibBench zero_copy() {
    LibBench r = row("zero-copy");
    if (level_ >= 2) {
      r.sweeps.push_back(sweep("VV", [this](uint64_t &n) {
        const uint32_t *V = che_mesh_half_edge_vertices(m_, nullptr), *O = che_mesh_opposites(m_, nullptr),
                       *VH = che_mesh_vertex_half_edges(m_, nullptr);
        uint64_t cs = 0;
        for (uint32_t v = 0; v < nv_; ++v) {
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
      r.sweeps.push_back(sweep("VF", [this](uint64_t &n) {
        const uint32_t *O = che_mesh_opposites(m_, nullptr), *VH = che_mesh_vertex_half_edges(m_, nullptr);
        uint64_t cs = 0;
        for (uint32_t v = 0; v < nv_; ++v) {
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
      r.sweeps.push_back(skipped_sweep("VV", "needs VH (level 2)"));
      r.sweeps.push_back(skipped_sweep("VF", "needs VH (level 2)"));
    }
    r.sweeps.push_back(sweep("FF", [this](uint64_t &n) {
      const uint32_t *O = che_mesh_opposites(m_, nullptr);
      uint64_t cs = 0;
      for (uint32_t h = 0; h < 3 * nt_; ++h)
        if (O[h] != TOPOMESH_NONE) cs += uint64_t(O[h] / 3 + 1) * (h / 3 + 1), ++n;
      return cs;
    }));
    r.sweeps.push_back(sweep("EF", [this](uint64_t &n) {
      const uint32_t *O = che_mesh_opposites(m_, nullptr);
      uint64_t cs = 0;
      for (uint32_t h = 0; h < 3 * nt_; ++h) {
        uint32_t g = O[h];
        if (g == TOPOMESH_NONE) cs += h / 3 + 1, ++n;
        else if (h < g) cs += h / 3 + 1 + g / 3 + 1, n += 2;
      }
      return cs;
    }));
    r.sweeps.push_back(sweep("curves", [this](uint64_t &n) {
      size_t nc = 0;
      const uint32_t *V = che_mesh_half_edge_vertices(m_, nullptr), *O = che_mesh_opposites(m_, nullptr),
                     *VH = che_mesh_vertex_half_edges(m_, nullptr), *CH = che_mesh_curve_half_edges(m_, &nc);
      const uint32_t nh = uint32_t(3 * nt_);
      auto next_boundary = [&](uint32_t h) {
        if (VH) return VH[V[nxt(h)]];
        uint32_t g = nxt(h); // level 1: rotate clockwise around the target to the boundary
        while (O[g] != TOPOMESH_NONE) g = nxt(O[g]);
        return g;
      };
      uint64_t cs = 0;
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
    return r;
  }

  const Soup &s_;
  const uint32_t level_;
  che_mesh *m_ = nullptr;
  size_t nv_ = 0, nt_ = 0, ne_ = 0, nb_ = 0, nc_ = 0;
};

// Interleaved repetitions: RSS first (one build each, alone), then `reps` rounds of builds
// (each round starts with a different subject), then `reps` rounds of every sweep of every
// row.
std::vector<LibBench> run(std::vector<std::unique_ptr<Subject>> &subjects, int reps) {
  const size_t n = subjects.size();
  std::vector<long> rss(n);
  for (size_t k = 0; k < n; ++k) {
    subjects[k]->release();
    long before = rss_bytes();
    subjects[k]->build();
    rss[k] = rss_bytes() - before;
    subjects[k]->release();
  }
  std::vector<std::vector<double>> build_ms(n), build_wall(n);
  for (int r = 0; r < reps; ++r)
    for (size_t i = 0; i < n; ++i) {
      size_t k = (i + size_t(r)) % n;
      subjects[k]->release();
      double w0 = now_ms(), t0 = cpu_ms();
      subjects[k]->build();
      build_ms[k].push_back(cpu_ms() - t0);
      build_wall[k].push_back(now_ms() - w0);
    }
  std::vector<LibBench> rows;
  for (size_t k = 0; k < n; ++k)
    for (LibBench &row : subjects[k]->rows()) {
      if (row.owns_build) {
        subjects[k]->describe(row);
        row.build_ms = build_ms[k];
        row.build_wall_ms = build_wall[k];
        row.rss_delta = rss[k];
      }
      rows.push_back(std::move(row));
    }
  for (const char *name : {"VV", "VF", "FF", "EF", "curves"})
    for (int r = 0; r < reps; ++r)
      for (size_t i = 0; i < rows.size(); ++i) {
        LibBench &row = rows[(i + size_t(r)) % rows.size()];
        for (Sweep &sw : row.sweeps) {
          if (sw.name != name || sw.skipped()) continue;
          uint64_t count = 0;
          double w0 = now_ms(), t0 = cpu_ms();
          uint64_t cs = sw.fn(count);
          sw.ms.push_back(cpu_ms() - t0);
          sw.wall_ms.push_back(now_ms() - w0);
          sw.checksum = cs;
          sw.count = count;
        }
      }
  // Build columns of the rows that share their subject's build.
  for (size_t i = 1; i < rows.size(); ++i)
    if (!rows[i].owns_build) {
      rows[i].faces = rows[i - 1].faces;
      rows[i].vertices = rows[i - 1].vertices;
      rows[i].note = rows[i - 1].note;
      rows[i].connectivity_bytes = rows[i - 1].connectivity_bytes;
    }
  return rows;
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
  out("%zu vertices, %zu triangles. Medians of %d runs; CPU milliseconds of the benchmark thread (the build's "
      "wall-clock time beside it; topomesh builds on one thread here, `threads` 1); memory in MiB.\n\n",
      s.n_vertices, s.n_triangles(), reps);
  out("| library | path | build | (wall) | connectivity | RSS growth | VV | VF | FF | EF | curves |\n");
  out("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (auto &r : rows) {
    bool first_of_build = r.owns_build;
    out("| %s | %s | %s | %s | %s | %s |", r.lib.c_str(), r.path.empty() ? "" : r.path.c_str(),
        first_of_build ? fmt_ms(median(r.build_ms)).c_str() : "″",
        first_of_build ? fmt_ms(median(r.build_wall_ms)).c_str() : "″",
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
    if (r.owns_build) build_row = &r;
    auto both = [&](double a, double b, double t) { return fmt_ratio(a, t) + " / " + fmt_ratio(b, t); };
    std::string b = !r.owns_build ? "″"
                                       : both(median(om.build_ms), median(cg.build_ms), median(r.build_ms));
    std::string mem = !r.owns_build ? "″"
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

  // The speed targets, on this mesh.
  auto find = [&](const std::string &lib, const std::string &path) -> const LibBench * {
    for (auto &r : rows)
      if (r.lib == lib && r.path == path) return &r;
    return nullptr;
  };
  const LibBench *l2 = find("topomesh L2", "C API"), *l1 = find("topomesh L1", "C API");
  double b2 = median(l2->build_ms), bo = median(om.build_ms), bc = median(cg.build_ms);
  out("\nTargets: level-2 build %s faster than OpenMesh, %s than CGAL (target 10×: %s); ",
      fmt_ratio2(bo, b2).c_str(), fmt_ratio2(bc, b2).c_str(), bo >= 10 * b2 && bc >= 10 * b2 ? "met" : "missed");
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
      out(" L2 %s %s%s", path, fmt_ratio2(peer, t).c_str(), t > 0 && peer >= 1.5 * t ? " met" : t > 0 ? " missed" : "");
    }
  }
  out(".\n");
}

} // namespace

int main(int argc, char **argv) {
  const char *usage = "topomesh_bench [--reps N] [--md FILE] MESH.off...";
  return bench_main(argc, argv, "bench", usage, [](const Soup &s, int reps, Out &out) {
    PeerInput in{s.n_vertices, s.positions.data(), s.triangles.data(), s.n_triangles()};
    std::vector<std::unique_ptr<Subject>> subjects;
    subjects.push_back(openmesh_subject(in));
    subjects.push_back(cgal_subject(in));
    for (uint32_t level = 1; level <= 3; ++level) subjects.push_back(std::make_unique<TmSubject>(s, level));
    std::vector<LibBench> rows = run(subjects, reps);
    report(out, s, rows, reps);
  });
}
