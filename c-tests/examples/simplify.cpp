// Shortest-edge-first simplification through the C++ wrapper: a torus of 2048 triangles
// collapsed to at most 400, refusing collapses that fail the link condition (the library
// refuses them) or would turn a triangle over; then garbage collection and the summary.
#include <topomesh/topomesh.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <queue>
#include <tuple>
#include <vector>

using namespace topomesh;

static Surface torus(std::uint32_t nu, std::uint32_t nv) {
    std::vector<double> xyz;
    std::vector<std::uint32_t> tris;
    for (std::uint32_t j = 0; j < nv; j++)
        for (std::uint32_t i = 0; i < nu; i++) {
            const double u = 6.283185307179586 * i / nu, v = 6.283185307179586 * j / nv;
            xyz.insert(xyz.end(), {(2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u),
                                   std::sin(v)});
            const std::uint32_t a = j * nu + i, b = j * nu + (i + 1) % nu,
                                c = ((j + 1) % nv) * nu + (i + 1) % nu, d = ((j + 1) % nv) * nu + i;
            tris.insert(tris.end(), {a, b, c, a, c, d});
        }
    return Surface::from_triangles(tris, std::size_t(nu) * nv, xyz);
}

static Vec3 sub(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
static Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
static double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static double length(const Surface &s, HalfEdgeId h) {
    const Vec3 d = sub(s.position(s.origin(h)), s.position(s.target(h)));
    return std::sqrt(dot(d, d));
}

// Would moving both ends of h to mid turn a triangle around them over?
static bool flips(const Surface &s, HalfEdgeId h, Vec3 mid) {
    const VertexId a = s.origin(h), b = s.target(h);
    for (VertexId x : {a, b})
        for (TriangleId t : s.vertex_triangles(x)) {
            const auto c = s.triangle_vertices(t);
            bool has_a = false, has_b = false;
            for (VertexId y : c) {
                has_a = has_a || y == a;
                has_b = has_b || y == b;
            }
            if (has_a && has_b) continue;
            auto at = [&](VertexId y) { return s.position(y); };
            auto moved = [&](VertexId y) { return y == a || y == b ? mid : s.position(y); };
            const Vec3 n0 = cross(sub(at(c[1]), at(c[0])), sub(at(c[2]), at(c[0])));
            const Vec3 n1 = cross(sub(moved(c[1]), moved(c[0])), sub(moved(c[2]), moved(c[0])));
            if (dot(n0, n1) <= 0) return true;
        }
    return false;
}

int main() {
    Surface s = torus(32, 32);
    const std::size_t before = s.num_triangles(), target = 400;
    using Entry = std::tuple<double, std::uint32_t, std::uint32_t, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    auto push = [&](HalfEdgeId h) {
        queue.emplace(length(s, h), h.value(), s.origin(h).value(), s.target(h).value());
    };
    for (EdgeId e : s.edges()) push(s.half_edge(e));
    std::size_t collapses = 0;
    while (s.num_live_triangles() > target && !queue.empty()) {
        const auto [len, hv, av, bv] = queue.top();
        queue.pop();
        const HalfEdgeId h{hv};
        if (s.is_removed(triangle_of(h)) || s.origin(h).value() != av ||
            s.target(h).value() != bv)
            continue;
        if (length(s, h) != len) {
            push(h);
            continue;
        }
        const Vec3 pa = s.position(VertexId{av}), pb = s.position(VertexId{bv});
        const Vec3 mid{(pa.x + pb.x) / 2, (pa.y + pb.y) / 2, (pa.z + pb.z) / 2};
        if (!s.is_collapse_ok(h) || flips(s, h, mid)) continue;
        const VertexId kept = s.collapse(h);
        s.set_position(kept, mid);
        collapses++;
        for (const StarStep &step : s.star(kept)) push(step.half_edge);
    }
    s.validate();
    const Surface::GarbageMaps maps = s.garbage_collect();
    s.validate();
    const auto sum = s.summary();
    std::printf("simplified %zu -> %zu triangles (%zu collapses, %zu old vertices mapped)\n",
                before, s.num_triangles(), collapses, maps.vertices.size());
    std::printf("euler=%lld genus=%lld manifold=%d\n", (long long)sum.euler_characteristic,
                (long long)sum.genus, (int)sum.manifold);
    // A refusal throws and changes nothing.
    try {
        s.flip(EdgeId{std::uint32_t(s.num_edges())});
        return 1;
    } catch (const Error &e) {
        std::printf("refused: %s\n", e.what());
    }
    return s.num_triangles() <= target ? 0 : 1;
}
