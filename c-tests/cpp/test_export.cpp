// The wrapper's exports (Surface::halfedge(), winged(), corner(), edge_list(),
// triangle_edges(), matrix(), betti(), strips(); Volume::halfface(), dual_graph(), matrix(),
// betti()) against the wrapper's own per-element relations, and the algebra they must obey
// (d1 d2 = 0, d2 d3 = 0, Euler characteristic, every triangle once in a strip).
#include "check.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

using namespace topomesh;

static const std::uint32_t N = none;

// An n x m grid on a torus (closed) or on a cylinder (open in the second direction).
static Surface grid(std::uint32_t n, std::uint32_t m, bool closed, std::uint32_t level) {
    std::vector<std::uint32_t> tris;
    const std::uint32_t rows = closed ? m : m + 1;
    auto id = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * rows + (closed ? j % m : j); };
    for (std::uint32_t i = 0; i < n; i++)
        for (std::uint32_t j = 0; j < m; j++) {
            tris.insert(tris.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            tris.insert(tris.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    Options o;
    o.level = level;
    return Surface::from_triangles(tris, n * rows, {}, o);
}

// The product of two CSR matrices over the integers, as a map of its non-zero entries.
static std::map<std::pair<std::size_t, std::uint32_t>, double> product(const CsrMatrix &a,
                                                                     const CsrMatrix &b) {
    std::map<std::pair<std::size_t, std::uint32_t>, double> out;
    for (std::size_t r = 0; r < a.rows; r++)
        for (std::uint64_t i = a.offsets[r]; i < a.offsets[r + 1]; i++) {
            const std::uint32_t k = a.columns[i];
            for (std::uint64_t j = b.offsets[k]; j < b.offsets[k + 1]; j++)
                out[{r, b.columns[j]}] += a.values[i] * b.values[j];
        }
    for (auto it = out.begin(); it != out.end();) it = it->second == 0 ? out.erase(it) : ++it;
    return out;
}

static void check_shape(const CsrMatrix &a, std::size_t rows, std::size_t cols) {
    CHECK(a.rows == rows && a.cols == cols && a.offsets.size() == rows + 1);
    CHECK(a.offsets.back() == a.nonzeros() && a.values.size() == a.nonzeros());
    for (std::uint32_t c : a.columns) CHECK(c < cols);
}

static void surface_arrays(const Surface &s) {
    const std::size_t nh = s.num_half_edges(), nt = s.num_triangles();
    HalfEdges he = s.halfedge();
    CHECK(he.next.size() == nh && he.twin.size() == nh && he.vertex.size() == nh);
    CHECK(he.face_half_edge.size() == nt && he.vertex_half_edge.size() == s.num_vertices());
    for (HalfEdgeId h : s.half_edges()) {
        const std::uint32_t i = h.value();
        CHECK(he.next[i] == next(h).value() && he.prev[i] == prev(h).value());
        CHECK(he.twin[i] == s.opposite(h).value() && he.vertex[i] == s.origin(h).value());
        CHECK(he.face[i] == i / 3 && he.edge[i] == s.edge(h).value());
    }
    for (VertexId v : s.vertices()) {
        const std::uint32_t h = he.vertex_half_edge[v.value()];
        CHECK(h == N || he.vertex[h] == v.value());
    }
    // Explicit boundary: every half-edge has a twin, the extra ones have no face and go
    // round the holes.
    HalfEdges ex = s.halfedge(HalfEdgeOptions{true});
    CHECK(ex.next.size() >= nh);
    for (std::size_t h = 0; h < ex.next.size(); h++) {
        CHECK(ex.twin[h] != N && ex.twin[ex.twin[h]] == h);
        CHECK(ex.prev[ex.next[h]] == h && ex.vertex[ex.next[h]] == ex.vertex[ex.twin[h]]);
        CHECK((h < nh) == (ex.face[h] != N));
    }

    WingedEdges w = s.winged();
    std::vector<std::uint32_t> el = s.edge_list();
    CHECK(w.vertices == el && el.size() == 2 * s.num_edges());
    for (EdgeId e : s.edges()) {
        auto ends = s.edge_vertices(e);
        CHECK(ends.size() == 2 && el[2 * e.value()] == ends[0].value() &&
              el[2 * e.value() + 1] == ends[1].value());
        const std::uint32_t left = w.faces[2 * e.value()], right = w.faces[2 * e.value() + 1];
        CHECK(left != N && (right == N) == s.is_boundary(e));
    }
    std::vector<std::uint32_t> te = s.triangle_edges();
    for (TriangleId t : s.triangles()) {
        auto edges = s.triangle_edges(t);
        for (std::uint32_t i = 0; i < 3; i++) CHECK(te[3 * t.value() + i] == edges[i].value());
        CHECK(w.face_edge[t.value()] == te[3 * t.value()]);
    }

    CornerTable c = s.corner();
    CHECK(c.V == he.vertex && c.O.size() == nh);
    for (HalfEdgeId h : s.half_edges()) {
        const HalfEdgeId g = s.opposite(next(h));
        CHECK(c.O[h.value()] == (g.valid() ? prev(g).value() : N));
    }
}

static void surface_matrices(const Surface &s) {
    const std::size_t nv = s.num_vertices(), ne = s.num_edges(), nt = s.num_triangles();
    CsrMatrix d1 = s.matrix(CHE_MATRIX_KIND_D1), d2 = s.matrix(CHE_MATRIX_KIND_D2);
    check_shape(d1, nv, ne);
    check_shape(d2, ne, nt);
    CHECK(d1.nonzeros() == 2 * ne && d2.nonzeros() == 3 * nt);
    CHECK(product(d1, d2).empty());
    CsrMatrix lap = s.matrix(CHE_MATRIX_KIND_LAPLACIAN), adj = s.matrix(CHE_MATRIX_KIND_VERTEX_ADJACENCY);
    check_shape(lap, nv, nv);
    check_shape(adj, nv, nv);
    for (VertexId v : s.vertices()) {
        double sum = 0;
        for (std::uint64_t i = lap.offsets[v.value()]; i < lap.offsets[v.value() + 1]; i++)
            sum += lap.values[i];
        CHECK(sum == 0);
        CHECK(adj.offsets[v.value() + 1] - adj.offsets[v.value()] + 1 ==
              lap.offsets[v.value() + 1] - lap.offsets[v.value()]);
    }
    CsrMatrix dual = s.matrix(CHE_MATRIX_KIND_DUAL_ADJACENCY);
    check_shape(dual, nt, nt);
    for (TriangleId t : s.triangles()) {
        std::vector<std::uint32_t> want;
        for (TriangleId u : s.triangle_triangles(t))
            if (u.valid()) want.push_back(u.value());
        std::sort(want.begin(), want.end());
        want.erase(std::unique(want.begin(), want.end()), want.end());
        std::vector<std::uint32_t> got(dual.columns.begin() + dual.offsets[t.value()],
                                       dual.columns.begin() + dual.offsets[t.value() + 1]);
        CHECK(got == want);
    }
    check_shape(s.matrix(CHE_MATRIX_KIND_EDGE_ADJACENCY), ne, ne);
}

// The triangles of a strip list with restarts, each rotated to start at its smallest id.
static std::vector<std::array<std::uint32_t, 3>> strip_triangles(const std::vector<std::uint32_t> &l) {
    std::vector<std::array<std::uint32_t, 3>> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= l.size(); i++) {
        if (i < l.size() && l[i] != N) continue;
        for (std::size_t k = start; k + 2 < i; k++) {
            std::array<std::uint32_t, 3> t = (k - start) % 2 == 0
                                                 ? std::array<std::uint32_t, 3>{l[k], l[k + 1], l[k + 2]}
                                                 : std::array<std::uint32_t, 3>{l[k + 1], l[k], l[k + 2]};
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue; // degenerate join
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            out.push_back(t);
        }
        start = i + 1;
    }
    std::sort(out.begin(), out.end());
    return out;
}

static void surface_strips(const Surface &s) {
    std::vector<std::array<std::uint32_t, 3>> want;
    for (TriangleId t : s.triangles()) {
        auto v = s.triangle_vertices(t);
        std::array<std::uint32_t, 3> a{v[0].value(), v[1].value(), v[2].value()};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        want.push_back(a);
    }
    std::sort(want.begin(), want.end());
    std::vector<std::uint32_t> restarts = s.strips(), joined = s.strips(StripList::joined);
    CHECK(strip_triangles(restarts) == want);
    CHECK(strip_triangles(joined) == want);
    CHECK(std::find(joined.begin(), joined.end(), N) == joined.end());
}

static void surfaces() {
    for (std::uint32_t level = 0; level <= 3; level++) {
        Surface torus = grid(6, 5, true, level), tube = grid(5, 4, false, level);
        for (const Surface *s : {&torus, &tube}) {
            surface_arrays(*s);
            surface_matrices(*s);
            surface_strips(*s);
        }
        SurfaceBetti b = torus.betti();
        CHECK(b.b0 == 1 && b.b1 == 2 && b.b2 == 1);
        b = tube.betti();
        CHECK(b.b0 == 1 && b.b1 == 1 && b.b2 == 0);
        CHECK(std::int64_t(b.b0) - std::int64_t(b.b1) + std::int64_t(b.b2) ==
              tube.summary().euler_characteristic);
    }
}

static void volumes() {
    // Two tetrahedra sharing a face, and one apart.
    const std::vector<std::uint32_t> tets = {0, 1, 2, 3, 1, 2, 3, 4, 5, 6, 7, 8};
    for (std::uint32_t level = 0; level <= 3; level++) {
        Options o;
        o.level = level;
        Volume vol = Volume::from_tetrahedra(tets, 9, {}, o);
        HalfFaces hf = vol.halfface();
        CHECK(hf.twin.size() == vol.num_half_faces() && hf.vertices.size() == 3 * hf.twin.size());
        for (HalfFaceId h : vol.half_faces()) {
            CHECK(hf.twin[h.value()] == vol.opposite(h).value());
            CHECK(hf.face[h.value()] == vol.face(h).value());
        }
        std::vector<std::uint32_t> dual = vol.dual_graph();
        for (TetrahedronId t : vol.tetrahedra()) {
            auto across = vol.tetrahedron_tetrahedra(t);
            for (std::uint32_t i = 0; i < 4; i++) CHECK(dual[4 * t.value() + i] == across[i].value());
        }
        CsrMatrix d1 = vol.matrix(CHF_MATRIX_KIND_D1), d2 = vol.matrix(CHF_MATRIX_KIND_D2),
                  d3 = vol.matrix(CHF_MATRIX_KIND_D3);
        check_shape(d1, vol.num_vertices(), vol.num_edges());
        check_shape(d2, vol.num_edges(), vol.num_faces());
        check_shape(d3, vol.num_faces(), vol.num_tetrahedra());
        CHECK(product(d1, d2).empty() && product(d2, d3).empty());
        check_shape(vol.matrix(CHF_MATRIX_KIND_DUAL_ADJACENCY), vol.num_tetrahedra(),
                    vol.num_tetrahedra());
        VolumeBetti b = vol.betti();
        CHECK(b.b0 == 2 && b.b1 == 0 && b.b2 == 0 && b.b3 == 0);
        SurfaceBetti skin = vol.boundary().betti();
        CHECK(skin.b0 == 2 && skin.b1 == 0 && skin.b2 == 2);
    }
}

int main() {
    return run_tests("test_export", [] {
        surfaces();
        volumes();
    });
}
