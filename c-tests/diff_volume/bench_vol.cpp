// Volume head-to-head: topomesh's CHF (C API, levels 1, 2, 3) against CGAL's Triangulation_3
// built by CGAL::build_triangulation, in one process, from the same arrays.
//
//   topomesh_bench_vol [--reps N] <dir/name> ...     tetgen meshes <dir/name>.node/.ele
//
// Prints, per mesh, Markdown tables (medians of N repetitions, default 5): build time from
// the soup, connectivity memory (from container sizes, and the resident-set growth and
// peak around one build), and full sweeps of TT, VT, ET, VV with their checksums (the
// number of entries visited: equal for every library on a manifold mesh), then the targets.
// Compile with -O2 (no -march=native).
#include "bench_vol_util.hpp"
#include "peer_cgal.hpp"
#include "tet_soup.hpp"

#include <CGAL/version.h>
#include <topomesh/topomesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <malloc.h>
#include <thread>
#include <string>
#include <vector>

using namespace diffvol;

namespace {

// `threads` 0: the library's default (every thread of the machine).
chf_mesh *tm_build(const TetSoup &s, uint32_t level, uint32_t threads = 0) {
  chf_mesh *m = nullptr;
  chf_build_options o = chf_build_options_default();
  o.level = level;
  o.threads = threads;
  topomesh_status st = chf_mesh_from_tetrahedra_ex(s.tets.data(), s.n_tets(), s.n_vertices, s.positions.data(), &o, &m);
  if (st != TOPOMESH_STATUS_OK) {
    std::fprintf(stderr, "topomesh build at level %u failed: %s\n", level, topomesh_status_str(st));
    std::exit(1);
  }
  return m;
}

struct Sweep {
  std::string lib, path, rel;
  double ms = -1;
  uint64_t checksum = 0;
};

template <class F> Sweep sweep(const std::string &lib, const std::string &path, const std::string &rel, int reps, F &&f) {
  Sweep s{lib, path, rel, -1, 0};
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    double t0 = now_ms();
    s.checksum = f();
    t.push_back(now_ms() - t0);
  }
  s.ms = median(t);
  return s;
}

using Relation = topomesh_status (*)(const chf_mesh *, uint32_t, uint32_t *, size_t, size_t *);
using CsrCall = topomesh_status (*)(const chf_mesh *, uint32_t *, size_t, uint32_t *, size_t, size_t *, size_t *);

// One per-element call for every id; counts entries (not NONE).
uint64_t per_element(const chf_mesh *m, Relation f, size_t n) {
  static thread_local std::vector<uint32_t> buf(4096);
  uint64_t c = 0;
  for (uint32_t i = 0; i < n; ++i) {
    size_t len = 0;
    if (f(m, i, buf.data(), buf.size(), &len) != TOPOMESH_STATUS_OK) {
      std::fprintf(stderr, "per-element call failed at %u (len %zu)\n", i, len);
      std::exit(1);
    }
    for (size_t k = 0; k < len; ++k) c += buf[k] != TOPOMESH_NONE;
  }
  return c;
}

// A bulk CSR call into arrays sized beforehand (size(), outside the timing: a size query
// does the whole work once more); counts entries (not NONE).
struct CsrBuf {
  std::vector<uint32_t> off, idx;
  CsrBuf &size(const chf_mesh *m, CsrCall f) {
    size_t no = 0, ni = 0;
    if (f(m, nullptr, 0, nullptr, 0, &no, &ni) != TOPOMESH_STATUS_OK) {
      std::fprintf(stderr, "CSR size query failed\n");
      std::exit(1);
    }
    off.resize(no), idx.resize(ni);
    return *this;
  }
};
uint64_t bulk(const chf_mesh *m, CsrCall f, CsrBuf &b) {
  size_t no = 0, ni = 0;
  if (f(m, b.off.data(), b.off.size(), b.idx.data(), b.idx.size(), &no, &ni) != TOPOMESH_STATUS_OK) {
    std::fprintf(stderr, "CSR call failed\n");
    std::exit(1);
  }
  uint64_t c = 0;
  for (size_t k = 0; k < ni; ++k) c += b.idx[k] != TOPOMESH_NONE;
  return c;
}

// What the library's default (threads 0) uses.
const unsigned n_threads = std::max(1u, std::thread::hardware_concurrency());

void bench(const std::string &base, int reps) {
  const TetSoup s = read_bench_tets(base);
  std::printf("\n### %s: %zu vertices, %zu tetrahedra\n\n", s.name.c_str(), s.n_vertices, s.n_tets());
  std::fflush(stdout);

  // Memory: one build of each, alone, RSS growth and peak around it.
  struct Mem {
    std::string lib;
    long structure = 0, structure_all = 0; // from container sizes: connectivity; with positions and maps
    long retained = -1, peak = -1;
  };
  std::vector<Mem> mem;
  CgalStats cst;
  {
    MemProbe p;
    p.begin();
    auto c = CgalVol::build(s, cst);
    p.end();
    if (!c) {
      std::printf("CGAL refused the mesh: %s\n", cst.refusal.c_str());
      std::exit(1);
    }
    Mem m{"CGAL Triangulation_3", 0, 0, p.retained(), p.peak_delta()};
    m.structure = long(cst.cells * cst.sizeof_cell + cst.vertices * (cst.sizeof_vertex - cst.sizeof_point));
    m.structure_all = long(cst.cells * cst.sizeof_cell + cst.vertices * cst.sizeof_vertex);
    mem.push_back(m);
  }
  malloc_trim(0);
  chf_memory tmem[4]{};
  for (uint32_t level = 1; level <= 3; ++level) {
    MemProbe p;
    p.begin();
    chf_mesh *m = tm_build(s, level);
    p.end();
    chf_mesh_memory(m, &tmem[level]);
    Mem r{"topomesh L" + std::to_string(level), long(tmem[level].topology),
          long(tmem[level].topology + tmem[level].positions + tmem[level].maps), p.retained(), p.peak_delta()};
    mem.push_back(r);
    chf_mesh_free(m);
    malloc_trim(0);
  }

  // Build times.
  // t_tm: one thread (as CGAL); t_all: the default, every thread of the machine.
  std::vector<double> t_cgal, t_conv, t_tm[4], t_all[4];
  for (int r = 0; r < reps; ++r) {
    CgalStats st;
    auto c = CgalVol::build(s, st);
    t_cgal.push_back(st.build_ms);
    t_conv.push_back(st.convert_ms);
    c.reset();
    for (uint32_t level = 1; level <= 3; ++level) {
      double t0 = now_ms();
      chf_mesh *m = tm_build(s, level, 1);
      t_tm[level].push_back(now_ms() - t0);
      chf_mesh_free(m);
      t0 = now_ms();
      m = tm_build(s, level, 0);
      t_all[level].push_back(now_ms() - t0);
      chf_mesh_free(m);
    }
  }
  double b_cgal = median(t_cgal), b_conv = median(t_conv);
  std::printf("Build from the soup (median of %d, ms; CGAL includes converting the arrays to its "
              "points and oriented cells: %s ms):\n\n", reps, ms(b_conv).c_str());
  std::printf("| | ms | CGAL / this |\n|---|---:|---:|\n");
  std::printf("| CGAL build_triangulation | %s | 1.00 |\n", ms(b_cgal).c_str());
  for (uint32_t level = 1; level <= 3; ++level)
    std::printf("| topomesh L%u, 1 thread | %s | %s |\n", level, ms(median(t_tm[level])).c_str(),
                ratio(b_cgal, median(t_tm[level])).c_str());
  for (uint32_t level = 1; level <= 3; ++level)
    std::printf("| topomesh L%u, %u threads (default) | %s | %s |\n", level, n_threads,
                ms(median(t_all[level])).c_str(), ratio(b_cgal, median(t_all[level])).c_str());

  std::printf("\nConnectivity memory (MiB). Structure: CGAL = %zu cells (%zu finite + one infinite per "
              "boundary face) x sizeof(Cell) %zu B + %zu vertices x (sizeof(Vertex) %zu B - sizeof(Point) %zu B); "
              "topomesh = chf_mesh_memory().topology. \"+ geometry\": CGAL with its points, topomesh with "
              "positions and origin maps. RSS: growth of the resident set over one build (retained) and its "
              "peak during the build (VmHWM after resetting it), both over the RSS before:\n\n",
              cst.cells, cst.finite_cells, cst.sizeof_cell, cst.vertices, cst.sizeof_vertex, cst.sizeof_point);
  std::printf("| | structure | / CGAL | + geometry | RSS retained | RSS peak | peak / retained |\n"
              "|---|---:|---:|---:|---:|---:|---:|\n");
  for (auto &m : mem)
    std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", m.lib.c_str(), mib(double(m.structure)).c_str(),
                ratio(double(m.structure), double(mem[0].structure)).c_str(), mib(double(m.structure_all)).c_str(),
                mib(double(m.retained)).c_str(), m.peak < 0 ? "-" : mib(double(m.peak)).c_str(),
                ratio(double(m.peak), double(m.retained)).c_str());
  std::printf("\nCGAL's Compact_container capacities: %zu cells, %zu vertices (%s MiB with capacity).\n",
              cst.cell_capacity, cst.vertex_capacity,
              mib(double(cst.cell_capacity * cst.sizeof_cell + cst.vertex_capacity * cst.sizeof_vertex)).c_str());

  // Sweeps.
  std::vector<Sweep> sw;
  {
    CgalStats st;
    auto c = CgalVol::build(s, st);
    sw.push_back(sweep("CGAL", "cell->neighbor", "TT", reps, [&] { return c->sweep_tt(); }));
    sw.push_back(sweep("CGAL", "finite_incident_cells", "VT", reps, [&] { return c->sweep_vt(); }));
    sw.push_back(sweep("CGAL", "incident_cells(edge) circulator", "ET", reps, [&] { return c->sweep_et(); }));
    sw.push_back(sweep("CGAL", "finite_adjacent_vertices", "VV", reps, [&] { return c->sweep_vv(); }));
  }
  for (uint32_t level : {1u, 2u, 3u}) {
    chf_mesh *m = tm_build(s, level);
    std::string lib = "topomesh L" + std::to_string(level);
    size_t nv = chf_mesh_num_vertices(m), nt = chf_mesh_num_tetrahedra(m), ne = chf_mesh_num_edges(m);
    sw.push_back(sweep(lib, "chf_tetrahedron_tetrahedra", "TT", reps, [&] { return per_element(m, chf_tetrahedron_tetrahedra, nt); }));
    if (level >= 2) {
      sw.push_back(sweep(lib, "chf_vertex_tetrahedra", "VT", reps, [&] { return per_element(m, chf_vertex_tetrahedra, nv); }));
      sw.push_back(sweep(lib, "chf_edge_tetrahedra", "ET", reps, [&] { return per_element(m, chf_edge_tetrahedra, ne); }));
      sw.push_back(sweep(lib, "chf_vertex_vertices", "VV", reps, [&] { return per_element(m, chf_vertex_vertices, nv); }));
    }
    CsrBuf a, b, c, d;
    a.size(m, chf_mesh_tetrahedron_tetrahedra_csr), b.size(m, chf_mesh_vertex_tetrahedra_csr);
    c.size(m, chf_mesh_edge_tetrahedra_csr), d.size(m, chf_mesh_vertex_vertices_csr);
    sw.push_back(sweep(lib, "CSR bulk", "TT", reps, [&] { return bulk(m, chf_mesh_tetrahedron_tetrahedra_csr, a); }));
    sw.push_back(sweep(lib, "CSR bulk", "VT", reps, [&] { return bulk(m, chf_mesh_vertex_tetrahedra_csr, b); }));
    sw.push_back(sweep(lib, "CSR bulk", "ET", reps, [&] { return bulk(m, chf_mesh_edge_tetrahedra_csr, c); }));
    sw.push_back(sweep(lib, "CSR bulk", "VV", reps, [&] { return bulk(m, chf_mesh_vertex_vertices_csr, d); }));
    size_t len = 0;
    const uint32_t *O = chf_mesh_opposites(m, &len);
    sw.push_back(sweep(lib, "zero-copy O view", "TT", reps, [&] {
      uint64_t n = 0;
      for (size_t h = 0; h < len; ++h) n += O[h] != TOPOMESH_NONE; // tet = O[h] / 4
      return n;
    }));
    chf_mesh_free(m);
  }
  std::printf("\nSweeps over every element (median of %d, ms; checksum = entries visited; ratio = CGAL "
              "time / this, > 1 is faster than CGAL). topomesh's per-element VT/ET/VV at level 1 are "
              "O(T) per call by design and not timed; CSR output arrays are sized (size query) and allocated "
              "once, outside the timing:\n\n", reps);
  std::printf("| relation | library | access | ms | vs CGAL | checksum |\n|---|---|---|---:|---:|---:|\n");
  bool checks_ok = true;
  for (const char *rel : {"TT", "VT", "ET", "VV"}) {
    const Sweep *cg = nullptr;
    for (auto &x : sw)
      if (x.lib == "CGAL" && x.rel == rel) cg = &x;
    for (auto &x : sw) {
      if (x.rel != rel) continue;
      bool same = x.checksum == cg->checksum;
      checks_ok &= same;
      std::printf("| %s | %s | %s | %s | %s | %llu%s |\n", rel, x.lib.c_str(), x.path.c_str(), ms(x.ms).c_str(),
                  ratio(cg->ms, x.ms).c_str(), (unsigned long long)x.checksum, same ? "" : " (differs)");
    }
  }

  // Targets.
  auto best = [&](const char *rel, const char *lib) {
    double b = -1;
    for (auto &x : sw)
      if (x.rel == rel && x.lib == lib && (b < 0 || x.ms < b)) b = x.ms;
    return b;
  };
  auto per = [&](const char *rel, const char *lib) {
    for (auto &x : sw)
      if (x.rel == rel && x.lib == lib && x.path.rfind("chf_", 0) == 0) return x.ms;
    return -1.0;
  };
  auto cgal_ms = [&](const char *rel) {
    for (auto &x : sw)
      if (x.rel == rel && x.lib == "CGAL") return x.ms;
    return -1.0;
  };
  double l2 = median(t_tm[2]);
  std::printf("\nTargets on %s:\n\n", s.name.c_str());
  auto line = [](const char *what, bool ok, const std::string &got) {
    std::printf("- %s: %s (%s)\n", what, got.c_str(), ok ? "met" : "MISSED");
  };
  line("level-2 build >= 20x faster than CGAL, 1 thread", b_cgal / l2 >= 20, ratio(b_cgal, l2) + "x");
  double l2_all = median(t_all[2]);
  line(("level-2 build >= 20x faster than CGAL, " + std::to_string(n_threads) + " threads (default)").c_str(),
       b_cgal / l2_all >= 20, ratio(b_cgal, l2_all) + "x");
  double r1 = double(mem[1].structure) / double(mem[0].structure);
  line("level-1 connectivity <= 0.4 of CGAL's", r1 <= 0.4, ratio(double(mem[1].structure), double(mem[0].structure)));
  for (size_t i = 1; i < mem.size(); ++i) {
    double pr = double(mem[i].peak) / double(mem[i].retained);
    line(("build peak <= 2x final size, " + mem[i].lib + " (RSS peak / RSS retained)").c_str(),
         mem[i].peak > 0 && pr <= 2.0, ratio(double(mem[i].peak), double(mem[i].retained)));
  }
  for (const char *rel : {"TT", "VT", "VV"}) {
    double c = cgal_ms(rel);
    double p2 = per(rel, "topomesh L2"), b2 = best(rel, "topomesh L2");
    std::string what = std::string(rel) + " sweep >= 2x faster than CGAL (L2, per-element C calls; best access)";
    line(what.c_str(), c / p2 >= 2, ratio(c, p2) + "x; " + ratio(c, b2) + "x");
  }
  std::printf("- checksums equal across libraries: %s\n", checks_ok ? "yes" : "NO");
  std::fflush(stdout);
}

} // namespace

int main(int argc, char **argv) {
  int reps = 5;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--reps") == 0 && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
    else meshes.push_back(argv[i]);
  }
  if (meshes.empty()) {
    std::fprintf(stderr, "usage: topomesh_bench_vol [--reps N] <dir/name> ...\n");
    return 2;
  }
  std::printf("topomesh %s; CGAL %s\n", topomesh_version(), CGAL_VERSION_STR);
  for (auto &m : meshes) bench(m, reps);
  return 0;
}
