// Refinement through the C++ wrapper's editing methods: the unit cube in 5 tetrahedra,
// the largest tetrahedron split 1-4 at its centroid until every volume is below a bound;
// then garbage collection and the summary (a ball: euler=1, one boundary sphere).
#include <topomesh/topomesh.hpp>

#include <cmath>
#include <cstdio>
#include <queue>
#include <utility>
#include <vector>

using namespace topomesh;

static double volume(const Volume &m, TetrahedronId t) {
    const auto q = m.tetrahedron_vertices(t);
    const Vec3 a = m.position(q[0]), b = m.position(q[1]), c = m.position(q[2]),
               d = m.position(q[3]);
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const double wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
    return (ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) /
           6.0;
}

int main() {
    const std::vector<std::uint32_t> cube = {0, 1, 2, 4, 3, 2, 1, 7, 5, 1, 4, 7,
                                             6, 4, 2, 7, 1, 2, 4, 7};
    std::vector<double> xyz;
    for (int v = 0; v < 8; v++) xyz.insert(xyz.end(), {double(v & 1), double(v >> 1 & 1), double(v >> 2)});
    Volume m = Volume::from_tetrahedra(cube, 8, xyz);
    const double bound = 0.002;
    std::priority_queue<std::pair<double, std::uint32_t>> largest;
    for (TetrahedronId t : m.tetrahedra()) largest.emplace(volume(m, t), t.value());
    std::size_t splits = 0;
    while (!largest.empty() && largest.top().first >= bound) {
        const TetrahedronId t{largest.top().second};
        largest.pop();
        const VertexId x = m.split(t);
        splits++;
        for (TetrahedronId s : m.vertex_tetrahedra(x)) largest.emplace(volume(m, s), s.value());
    }
    double total = 0, most = 0;
    for (TetrahedronId t : m.tetrahedra()) {
        if (m.is_removed(t)) continue;
        total += volume(m, t);
        most = std::fmax(most, volume(m, t));
    }
    std::printf("refined 5 -> %zu tetrahedra in %zu splits, max volume %.6f < %.3f, total %.6f\n",
                m.num_live_tetrahedra(), splits, most, bound, total);
    const auto maps = m.garbage_collect();
    m.validate();
    const auto s = m.summary();
    std::printf("V=%zu T=%zu euler=%lld boundary components=%zu manifold=%d\n", s.vertices,
                s.tetrahedra, static_cast<long long>(s.euler_characteristic),
                s.boundary_components, int(s.manifold));
    try {
        m.split(TetrahedronId{static_cast<std::uint32_t>(maps.tetrahedra.size())});
    } catch (const Error &e) {
        std::printf("refused: %s\n", e.what());
    }
    return most < bound && std::fabs(total - 1.0) < 1e-9 ? 0 : 1;
}
