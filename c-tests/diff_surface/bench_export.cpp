// Export benchmark: what a user saves by taking a classic representation from topomesh
// instead of building it with another library, in one process, from the same arrays.
//
//   topomesh_bench_export [--reps N] [--md FILE] MESH.off...
//
// Per mesh, medians of N repetitions (CPU time of the benchmark thread, interleaved across
// the tasks as bench.cpp does):
// - half-edge arrays (next, prev, twin, vertex, face, edge, vertex and face half-edge,
//   OpenMesh-style explicit boundary) from a built CHE, and build + export, against
//   building OpenMesh's TriMesh from the arrays (the half-edge structure a user would
//   otherwise make);
// - the combinatorial Laplacian as CSR from a built CHE against assembling it from a built
//   TriMesh's one-rings and against Eigen triplets from the triangle arrays (when Eigen is
//   found);
// - triangle strips from a built CHE (restarts and degenerate joins) against
//   meshopt_stripify (when meshoptimizer is found): time and index count;
// - Betti numbers against the build time.
// Output buffers are sized (size query) and allocated once, outside the timing. Checksums
// fold every entry so nothing is optimised away and the peers' answers can be compared;
// the Laplacians' are taken right after each run, untimed (reading 200 MB back is not
// part of making the matrix).
#include "bench_util.hpp"
#include "off_reader.hpp"

#include <topomesh/topomesh.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#if TOPOMESH_BENCH_EIGEN
#include <Eigen/SparseCore>
#endif
#if TOPOMESH_BENCH_MESHOPT
#include <meshoptimizer.h>
#endif

#include <cstring>
#include <memory>

using namespace diffmesh;

namespace {

struct OmTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using OMesh = OpenMesh::TriMesh_ArrayKernelT<OmTraits>;

void check(topomesh_status s, const char *what) {
  if (s != TOPOMESH_STATUS_OK) {
    char detail[512] = "";
    size_t len = 0;
    topomesh_last_error(detail, sizeof detail, &len);
    std::fprintf(stderr, "bench_export: %s: %s (%s)\n", what, topomesh_status_str(s), detail);
    std::exit(1);
  }
}

// A timed piece of work: `setup` (untimed) before each run, then `body` (timed), which
// returns a checksum, or `verify` (untimed, right after the body) does when it is set, so
// that checking what was made is not timed with making it.
struct Task {
  std::string name;
  std::function<void()> setup;
  std::function<uint64_t()> body;
  std::function<uint64_t()> verify;
  std::vector<double> ms;
  uint64_t checksum = 0;
};

// Round r runs every task once, from a different first one, so that load from other jobs
// spreads over all of them.
void run_tasks(std::vector<Task> &tasks, int reps) {
  const size_t n = tasks.size();
  for (int r = 0; r < reps; ++r)
    for (size_t i = 0; i < n; ++i) {
      Task &t = tasks[(i + size_t(r)) % n];
      if (t.setup) t.setup();
      double t0 = cpu_ms();
      t.checksum = t.body();
      t.ms.push_back(cpu_ms() - t0);
      if (t.verify) t.checksum = t.verify();
    }
}

che_mesh *build_che(const Soup &s, uint32_t level) {
  che_build_options o = che_build_options_default();
  o.level = level;
  o.threads = 1; // as the peers
  che_mesh *m = nullptr;
  check(che_mesh_from_triangles_ex(s.triangles.data(), s.n_triangles(), s.n_vertices, s.positions.data(), &o, &m),
        "build");
  return m;
}

void build_openmesh(const Soup &s, OMesh &m) {
  m.reserve(s.n_vertices, s.n_triangles() * 3 / 2 + 16, s.n_triangles());
  for (size_t v = 0; v < s.n_vertices; ++v) {
    const double *p = &s.positions[3 * v];
    m.add_vertex(OMesh::Point(p[0], p[1], p[2]));
  }
  for (size_t t = 0; t < s.n_triangles(); ++t) {
    const uint32_t *c = &s.triangles[3 * t];
    m.add_face(OpenMesh::VertexHandle(int(c[0])), OpenMesh::VertexHandle(int(c[1])),
               OpenMesh::VertexHandle(int(c[2])));
  }
}

// ---- half-edge arrays ----

constexpr che_half_edge_array kHalfEdgeArrays[] = {
    CHE_HALF_EDGE_ARRAY_NEXT, CHE_HALF_EDGE_ARRAY_PREV,        CHE_HALF_EDGE_ARRAY_TWIN,
    CHE_HALF_EDGE_ARRAY_VERTEX, CHE_HALF_EDGE_ARRAY_FACE,      CHE_HALF_EDGE_ARRAY_EDGE,
    CHE_HALF_EDGE_ARRAY_VERTEX_HALF_EDGE, CHE_HALF_EDGE_ARRAY_FACE_HALF_EDGE};

struct HalfEdgeBuffers {
  std::vector<std::vector<uint32_t>> arrays;
  void size_for(const che_mesh *m, const che_half_edge_options &o) {
    arrays.resize(std::size(kHalfEdgeArrays));
    for (size_t k = 0; k < arrays.size(); ++k) {
      size_t len = 0;
      che_mesh_export_half_edges(m, &o, kHalfEdgeArrays[k], nullptr, 0, &len);
      arrays[k].assign(len, 0);
    }
  }
  uint64_t fill(const che_mesh *m, const che_half_edge_options &o) {
    uint64_t cs = 0;
    for (size_t k = 0; k < arrays.size(); ++k) {
      size_t len = 0;
      check(che_mesh_export_half_edges(m, &o, kHalfEdgeArrays[k], arrays[k].data(), arrays[k].size(), &len),
            "half-edge export");
      cs += len + (len ? arrays[k][len / 2] : 0);
    }
    return cs;
  }
};

// ---- the Laplacian as CSR ----

struct Csr {
  std::vector<uint64_t> offsets;
  std::vector<uint32_t> columns;
  std::vector<double> values;
  size_t rows = 0, entries = 0;
};

// Every entry folded in, so that two assemblies of the same matrix give the same number.
uint64_t csr_checksum(const Csr &c) {
  uint64_t cs = 0;
  for (size_t r = 0; r < c.rows; ++r)
    for (uint64_t k = c.offsets[r]; k < c.offsets[r + 1]; ++k)
      cs += (r + 1) * (uint64_t(c.columns[k]) + 1) * uint64_t(int64_t(c.values[k]) + 8);
  return cs + c.entries;
}

uint64_t laplacian_topomesh(const che_mesh *m, Csr &c) {
  size_t no = 0, ne = 0;
  check(che_mesh_export_matrix(m, CHE_MATRIX_KIND_LAPLACIAN, c.offsets.data(), c.offsets.size(), c.columns.data(),
                               c.columns.size(), c.values.data(), c.values.size(), &no, &ne),
        "Laplacian export");
  c.rows = no - 1;
  c.entries = ne;
  return 0;
}

// Row v: its one-ring sorted, the degree on the diagonal.
uint64_t laplacian_openmesh(const OMesh &m, Csr &c) {
  std::vector<uint32_t> ring;
  uint64_t k = 0;
  c.offsets[0] = 0;
  for (auto vh : m.vertices()) {
    ring.clear();
    for (auto w : m.vv_range(vh)) ring.push_back(uint32_t(w.idx()));
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    const uint32_t v = uint32_t(vh.idx());
    const double degree = double(ring.size());
    bool diag = false;
    for (uint32_t w : ring) {
      if (!diag && w > v) c.columns[k] = v, c.values[k++] = degree, diag = true;
      c.columns[k] = w, c.values[k++] = -1;
    }
    if (!diag) c.columns[k] = v, c.values[k++] = degree;
    c.offsets[size_t(v) + 1] = k;
  }
  c.rows = m.n_vertices();
  c.entries = k;
  return 0;
}

#if TOPOMESH_BENCH_EIGEN
using EigenCsr = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// Off-diagonal -1 once per neighbour (duplicates kept once), then the degree on the
// diagonal (a zero triplet reserves its place).
uint64_t laplacian_eigen(const Soup &s, EigenCsr &L) {
  std::vector<Eigen::Triplet<double, int>> trip;
  trip.reserve(6 * s.n_triangles() + s.n_vertices);
  for (size_t v = 0; v < s.n_vertices; ++v) trip.emplace_back(int(v), int(v), 0.0);
  for (size_t t = 0; t < s.n_triangles(); ++t) {
    const uint32_t *c = &s.triangles[3 * t];
    for (int i = 0; i < 3; ++i) {
      int a = int(c[i]), b = int(c[(i + 1) % 3]);
      trip.emplace_back(a, b, -1.0);
      trip.emplace_back(b, a, -1.0);
    }
  }
  L.resize(int(s.n_vertices), int(s.n_vertices));
  L.setFromTriplets(trip.begin(), trip.end(), [](const double &a, const double &) { return a; });
  for (int r = 0; r < L.outerSize(); ++r) {
    double degree = 0;
    double *diag = nullptr;
    for (EigenCsr::InnerIterator it(L, r); it; ++it)
      if (it.col() == r) diag = &it.valueRef();
      else degree += 1;
    *diag = degree;
  }
  return 0;
}

// The checksum of csr_checksum over an Eigen matrix.
uint64_t eigen_checksum(const EigenCsr &L) {
  uint64_t cs = 0;
  for (int r = 0; r < L.outerSize(); ++r)
    for (EigenCsr::InnerIterator it(L, r); it; ++it)
      cs += uint64_t(r + 1) * (uint64_t(it.col()) + 1) * uint64_t(int64_t(it.value()) + 8);
  return cs + uint64_t(L.nonZeros());
}
#endif

// ---- strips ----

struct StripResult {
  size_t indices = 0, strips = 0;
};

StripResult strips_topomesh(const che_mesh *m, che_strip_list which, std::vector<uint32_t> &buf) {
  size_t len = 0;
  check(che_mesh_export_strips(m, which, buf.data(), buf.size(), &len), "strips");
  StripResult r{len, len ? 1u : 0u};
  for (size_t i = 0; i < len; ++i) r.strips += buf[i] == TOPOMESH_NONE;
  return r;
}


// Every task of one mesh, and the state they share (built outside the timing).
struct MeshBench {
  const Soup &s;
  int reps;
  che_mesh *che[3] = {nullptr, nullptr, nullptr};
  OMesh om_built;
  std::unique_ptr<OMesh> om_fresh;
  che_mesh *che_fresh = nullptr;
  che_half_edge_options explicit_boundary{true};
  HalfEdgeBuffers he;
  Csr csr, csr_om;
  std::vector<uint32_t> strip_buf, meshopt_buf, meshopt_order;
  StripResult strip_res[3][2], meshopt_res[4];
  che_betti betti{};
#if TOPOMESH_BENCH_EIGEN
  EigenCsr eigen_L;
#endif
  std::vector<Task> tasks;

  MeshBench(const Soup &soup, int r) : s(soup), reps(r) {
    static bool quiet = (::omerr().disable(), true); // "complex edge" etc.
    (void)quiet;
    for (uint32_t l = 0; l < 3; ++l) che[l] = build_che(s, l + 1);
    build_openmesh(s, om_built);
    he.size_for(che[0], explicit_boundary);
    size_t no = 0, ne = 0;
    check(che_mesh_export_matrix(che[0], CHE_MATRIX_KIND_LAPLACIAN, nullptr, 0, nullptr, 0, nullptr, 0, &no, &ne),
          "Laplacian size");
    for (Csr *c : {&csr, &csr_om}) {
      c->offsets.assign(no, 0);
      c->columns.assign(ne + s.n_vertices, 0); // a peer may see a few more entries
      c->values.assign(ne + s.n_vertices, 0);
    }
    size_t a = 0, b = 0;
    check(che_mesh_export_strips(che[0], CHE_STRIP_LIST_RESTARTS, nullptr, 0, &a), "strip size");
    check(che_mesh_export_strips(che[0], CHE_STRIP_LIST_JOINED, nullptr, 0, &b), "strip size");
    strip_buf.assign(std::max(a, b) + 16, 0);
  }
  ~MeshBench() {
    for (che_mesh *m : che) che_mesh_free(m);
    che_mesh_free(che_fresh);
  }
  MeshBench(const MeshBench &) = delete;
  MeshBench &operator=(const MeshBench &) = delete;

  void add(const std::string &name, std::function<uint64_t()> body, std::function<void()> setup = nullptr,
           std::function<uint64_t()> verify = nullptr) {
    tasks.push_back(Task{name, std::move(setup), std::move(body), std::move(verify), {}, 0});
  }
  void free_fresh() {
    om_fresh.reset();
    che_mesh_free(che_fresh);
    che_fresh = nullptr;
  }

  void add_builds() {
    add("OpenMesh build", [this] {
      om_fresh = std::make_unique<OMesh>();
      build_openmesh(s, *om_fresh);
      return uint64_t(om_fresh->n_halfedges());
    }, [this] { free_fresh(); });
    for (uint32_t l = 1; l <= 3; ++l)
      add("build L" + std::to_string(l), [this, l] {
        che_fresh = build_che(s, l);
        return uint64_t(che_mesh_num_edges(che_fresh));
      }, [this] { free_fresh(); });
  }
  void add_half_edges() {
    for (uint32_t l = 1; l <= 3; ++l) {
      add("half-edge L" + std::to_string(l), [this, l] { return he.fill(che[l - 1], explicit_boundary); });
      add("build+half-edge L" + std::to_string(l), [this, l] {
        che_fresh = build_che(s, l);
        return he.fill(che_fresh, explicit_boundary);
      }, [this] { free_fresh(); });
    }
  }
  void add_laplacians() {
    auto ours = [this] { return csr_checksum(csr); };
    for (uint32_t l = 1; l <= 3; ++l)
      add("laplacian L" + std::to_string(l), [this, l] { return laplacian_topomesh(che[l - 1], csr); }, nullptr, ours);
    add("build+laplacian L1", [this] {
      che_fresh = build_che(s, 1);
      return laplacian_topomesh(che_fresh, csr);
    }, [this] { free_fresh(); }, ours);
    add("laplacian OpenMesh", [this] { return laplacian_openmesh(om_built, csr_om); }, nullptr,
        [this] { return csr_checksum(csr_om); });
#if TOPOMESH_BENCH_EIGEN
    add("laplacian Eigen", [this] { return laplacian_eigen(s, eigen_L); }, [this] { eigen_L = EigenCsr(); },
        [this] { return eigen_checksum(eigen_L); });
#endif
  }
  void add_strips() {
    const che_strip_list kinds[2] = {CHE_STRIP_LIST_RESTARTS, CHE_STRIP_LIST_JOINED};
    for (uint32_t l = 1; l <= 3; ++l)
      for (int k = 0; k < 2; ++k)
        add("strips L" + std::to_string(l) + (k ? " joined" : " restarts"), [this, l, k, kinds] {
          strip_res[l - 1][k] = strips_topomesh(che[l - 1], kinds[k], strip_buf);
          return uint64_t(strip_res[l - 1][k].indices);
        });
#if TOPOMESH_BENCH_MESHOPT
    // meshoptimizer strips the triangles in the order given; its documentation reorders them
    // first with meshopt_optimizeVertexCacheStrip, timed here with the stripify.
    meshopt_buf.assign(meshopt_stripifyBound(s.triangles.size()), 0);
    meshopt_order.assign(s.triangles.size(), 0);
    for (int k = 0; k < 4; ++k)
      add(std::string("strips meshopt") + (k & 1 ? " joined" : " restarts") + (k & 2 ? " reordered" : ""), [this, k] {
        const unsigned restart = k & 1 ? 0u : ~0u;
        const uint32_t *in = s.triangles.data();
        if (k & 2) {
          meshopt_optimizeVertexCacheStrip(meshopt_order.data(), in, s.triangles.size(), s.n_vertices);
          in = meshopt_order.data();
        }
        size_t n = meshopt_stripify(meshopt_buf.data(), in, s.triangles.size(), s.n_vertices, restart);
        StripResult r{n, n ? 1u : 0u};
        if (!(k & 1))
          for (size_t i = 0; i < n; ++i) r.strips += meshopt_buf[i] == ~0u;
        meshopt_res[k] = r;
        return uint64_t(n);
      });
#endif
  }
  void add_betti() {
    for (uint32_t l = 1; l <= 3; ++l)
      add("betti L" + std::to_string(l), [this, l] {
        check(che_mesh_betti_numbers(che[l - 1], &betti), "Betti numbers");
        return betti.b0 + 3 * betti.b1 + 7 * betti.b2;
      });
  }

  const Task &task(const std::string &name) const {
    for (const Task &t : tasks)
      if (t.name == name) return t;
    std::fprintf(stderr, "bench_export: no task %s\n", name.c_str());
    std::exit(1);
  }
  double ms(const std::string &name) const { return median(task(name).ms); }
  bool has(const std::string &name) const {
    for (const Task &t : tasks)
      if (t.name == name) return true;
    return false;
  }
};

void report_half_edges(Out &out, const MeshBench &b) {
  const double om = b.ms("OpenMesh build");
  out("\nHalf-edge arrays (next, prev, twin, vertex, face, edge, one half-edge per vertex and per face; "
      "boundary half-edges explicit, as OpenMesh's), ms; ratio = OpenMesh build ÷ this:\n\n");
  out("| | ms | OpenMesh ÷ this |\n|---|---:|---:|\n");
  out("| OpenMesh TriMesh from the arrays (reserve, add_vertex, add_face) | %s | 1.00× |\n", fmt_ms(om).c_str());
  for (int l = 1; l <= 3; ++l) {
    std::string L = std::to_string(l);
    out("| topomesh L%d export from a built CHE | %s | %s |\n", l, fmt_ms(b.ms("half-edge L" + L)).c_str(),
        fmt_ratio2(om, b.ms("half-edge L" + L)).c_str());
    out("| topomesh L%d build + export | %s | %s |\n", l, fmt_ms(b.ms("build+half-edge L" + L)).c_str(),
        fmt_ratio2(om, b.ms("build+half-edge L" + L)).c_str());
  }
}

void report_laplacian(Out &out, const MeshBench &b) {
  const double om = b.ms("laplacian OpenMesh");
  const double eg = b.has("laplacian Eigen") ? b.ms("laplacian Eigen") : -1;
  out("\nThe Laplacian (degree minus adjacency) as CSR, %zu rows, %zu entries, ms; ratios = the peer ÷ this "
      "(OpenMesh's one-rings from a built TriMesh; Eigen's setFromTriplets from the triangle array)%s:\n\n",
      b.csr.rows, b.csr.entries, eg < 0 ? "; Eigen not found at configure time" : "");
  out("| | ms | OpenMesh ÷ this | Eigen ÷ this |\n|---|---:|---:|---:|\n");
  out("| OpenMesh one-rings (vv_range, sorted) | %s | 1.00× | %s |\n", fmt_ms(om).c_str(), fmt_ratio2(eg, om).c_str());
  out("| Eigen triplets + setFromTriplets | %s | %s | %s |\n", fmt_ms(eg).c_str(), fmt_ratio2(om, eg).c_str(),
      eg < 0 ? "–" : "1.00×");
  for (int l = 1; l <= 3; ++l) {
    double t = b.ms("laplacian L" + std::to_string(l));
    out("| topomesh L%d che_mesh_export_matrix (built CHE) | %s | %s | %s |\n", l, fmt_ms(t).c_str(),
        fmt_ratio2(om, t).c_str(), fmt_ratio2(eg, t).c_str());
  }
  double t = b.ms("build+laplacian L1");
  out("| topomesh L1 build + export | %s | %s | %s |\n", fmt_ms(t).c_str(), fmt_ratio2(om, t).c_str(),
      fmt_ratio2(eg, t).c_str());
  const uint64_t ref = b.task("laplacian L1").checksum;
  bool same = b.task("laplacian OpenMesh").checksum == ref &&
              (!b.has("laplacian Eigen") || b.task("laplacian Eigen").checksum == ref);
  for (int l = 2; l <= 3; ++l) same = same && b.task("laplacian L" + std::to_string(l)).checksum == ref;
  out("\nChecksum %llu: %s.\n", (unsigned long long)ref,
      same ? "every assembly gives the same matrix" : "the assemblies DIFFER");
}

void report_strips(Out &out, const MeshBench &b) {
  out("\nTriangle strips, %zu triangles: indices written (restart markers and degenerate joins included), "
      "strips, ms; ratios = meshoptimizer ÷ this, against the meshoptimizer pipeline with fewer indices "
      "(index count: above 1 is fewer indices than meshoptimizer)%s:\n\n",
      b.s.n_triangles(), b.has("strips meshopt restarts") ? "" : "; meshoptimizer not found at configure time");
  out("| | list | indices | strips | ms | indices: meshopt ÷ this | time: meshopt ÷ this |\n"
      "|---|---|---:|---:|---:|---:|---:|\n");
  const char *kind[2] = {"restarts", "joined"};
  for (int k = 0; k < 2; ++k) {
    std::string mo_name = std::string("strips meshopt ") + kind[k];
    const bool mo = b.has(mo_name);
    // The ratios against the better of meshoptimizer's two pipelines (fewer indices).
    int best = mo && b.meshopt_res[k + 2].indices < b.meshopt_res[k].indices ? k + 2 : k;
    const std::string best_name = mo_name + (best & 2 ? " reordered" : "");
    const double mo_ms = mo ? b.ms(best_name) : -1, mo_idx = mo ? double(b.meshopt_res[best].indices) : -1;
    for (int r = 0; mo && r < 2; ++r) {
      const StripResult &m = b.meshopt_res[k + 2 * r];
      const std::string name = mo_name + (r ? " reordered" : "");
      out("| meshopt_stripify%s | %s | %zu | %s | %s | %s | %s |\n", r ? " after optimizeVertexCacheStrip" : "",
          kind[k], m.indices, k ? "–" : std::to_string(m.strips).c_str(), fmt_ms(b.ms(name)).c_str(),
          fmt_ratio2(mo_idx, double(m.indices)).c_str(), fmt_ratio2(mo_ms, b.ms(name)).c_str());
    }
    for (int l = 1; l <= 3; ++l) {
      const StripResult &r = b.strip_res[l - 1][k];
      double t = b.ms("strips L" + std::to_string(l) + " " + kind[k]);
      out("| topomesh L%d | %s | %zu | %s | %s | %s | %s |\n", l, kind[k], r.indices,
          k ? "–" : std::to_string(r.strips).c_str(), fmt_ms(t).c_str(), fmt_ratio2(mo_idx, double(r.indices)).c_str(),
          fmt_ratio2(mo_ms, t).c_str());
    }
  }
}

void report_betti(Out &out, const MeshBench &b) {
  out("\nBetti numbers over Z/2 (b0 %llu, b1 %llu, b2 %llu) from a built CHE, against the build of that "
      "level (1 thread), ms:\n\n",
      (unsigned long long)b.betti.b0, (unsigned long long)b.betti.b1, (unsigned long long)b.betti.b2);
  out("| level | build | Betti numbers | Betti ÷ build |\n|---|---:|---:|---:|\n");
  for (int l = 1; l <= 3; ++l) {
    std::string L = std::to_string(l);
    double bt = b.ms("build L" + L), be = b.ms("betti L" + L);
    out("| topomesh L%d | %s | %s | %s |\n", l, fmt_ms(bt).c_str(), fmt_ms(be).c_str(), fmt_ratio2(be, bt).c_str());
  }
}

} // namespace

int main(int argc, char **argv) {
  const char *usage = "topomesh_bench_export [--reps N] [--md FILE] MESH.off...";
  return bench_main(argc, argv, "bench_export", usage, [](const Soup &s, int reps, Out &out) {
    MeshBench b(s, reps);
    b.add_builds();
    b.add_half_edges();
    b.add_laplacians();
    b.add_strips();
    b.add_betti();
    run_tasks(b.tasks, reps);
    out("\n### Exports: %s\n\n%zu vertices, %zu triangles. Medians of %d runs; CPU milliseconds of the benchmark "
        "thread; topomesh on one thread.\n",
        s.name.c_str(), s.n_vertices, s.n_triangles(), reps);
    report_half_edges(out, b);
    report_laplacian(out, b);
    report_strips(out, b);
    report_betti(out, b);
  });
}
