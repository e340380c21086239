// Concurrent stress of the C++ wrapper: 8 threads share one const Surface and one const
// Volume, and one const StarRange, Ids and Span per element built before they start; each
// thread iterates all of them and runs every per-element relation, and compares with the
// answers of one thread alone. Run under ThreadSanitizer or helgrind by scripts/sanitize.sh.
//
// Usage: test_stress_cpp [GRID [ROUNDS]] (defaults 12 and 2; GRID as in test_stress.c).
#include <topomesh/topomesh.hpp>

#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

using namespace topomesh;

namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t x) { return (h ^ x) * 0x100000001b3ULL + 0x9e3779b9; }

template <class R> std::uint64_t digest(std::uint64_t h, const R &range) {
    for (auto id : range) h = mix(h, id.value());
    return mix(h, 0xffff);
}

Surface grid(std::uint32_t g) {
    std::vector<std::uint32_t> tris;
    for (std::uint32_t y = 0; y < g; y++)
        for (std::uint32_t x = 0; x < g; x++) {
            std::uint32_t a = y * (g + 1) + x, b = a + 1, c = a + g + 1, d = c + 1;
            tris.insert(tris.end(), {a, b, d, a, d, c});
        }
    return Surface::from_triangles(tris, std::size_t(g + 1) * (g + 1));
}

Volume block(std::uint32_t k) {
    const std::uint32_t m = k + 1;
    const int path[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
    std::vector<std::uint32_t> tets;
    for (std::uint32_t z = 0; z < k; z++)
        for (std::uint32_t y = 0; y < k; y++)
            for (std::uint32_t x = 0; x < k; x++) {
                std::uint32_t c[8];
                for (int i = 0; i < 8; i++)
                    c[i] = ((z + (i >> 2 & 1)) * m + y + (i >> 1 & 1)) * m + x + (i & 1);
                for (auto &p : path) tets.insert(tets.end(), {c[0], c[p[0]], c[p[1]], c[7]});
            }
    return Volume::from_tetrahedra(tets, std::size_t(m) * m * m);
}

// Relations `rel...` of every element 0..n-1 of m, element by element.
template <class Id, class M, class... R>
std::uint64_t digest_all(std::uint64_t h, const M &m, std::uint32_t n, R (M::*... rel)(Id) const) {
    for (std::uint32_t i = 0; i < n; i++) ((h = digest(h, (m.*rel)(Id{i}))), ...);
    return h;
}

// Every relation of every element of both meshes, through the wrapper.
std::uint64_t relations(const Surface &s, const Volume &v) {
    std::uint64_t h = 1;
    h = digest_all(h, s, s.num_vertices(), &Surface::vertex_vertices, &Surface::vertex_edges,
                   &Surface::vertex_triangles);
    h = digest_all(h, s, s.num_edges(), &Surface::edge_vertices, &Surface::edge_edges,
                   &Surface::edge_triangles);
    h = digest_all(h, s, s.num_triangles(), &Surface::triangle_vertices,
                   &Surface::triangle_edges, &Surface::triangle_triangles);
    h = digest_all(h, v, v.num_vertices(), &Volume::vertex_vertices, &Volume::vertex_tetrahedra);
    h = digest_all(h, v, v.num_faces(), &Volume::face_tetrahedra);
    h = digest_all(h, v, v.num_tetrahedra(), &Volume::tetrahedron_tetrahedra);
    return h;
}

// The shared ranges, built once and only read by the threads.
struct Shared {
    std::vector<StarRange> stars;
    std::vector<Ids<VertexId>> rings;
    Span<std::uint32_t> origins;
};

std::uint64_t ranges(const Shared &shared) {
    std::uint64_t h = 1;
    for (const StarRange &star : shared.stars)
        for (const StarStep &step : star) h = mix(mix(h, step.vertex.value()), step.triangle.value());
    for (const auto &ring : shared.rings) h = digest(h, ring);
    for (std::uint32_t o : shared.origins) h = mix(h, o);
    return h;
}

}  // namespace

int main(int argc, char **argv) {
    const std::uint32_t g = argc > 1 ? std::uint32_t(std::atoi(argv[1])) : 12;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 2;
    const Surface s = grid(g);
    const Volume v = block(g / 2 > 0 ? g / 2 : 1);
    Shared shared;
    for (std::uint32_t i = 0; i < s.num_vertices(); i++) {
        shared.stars.push_back(s.star(VertexId{i}));
        shared.rings.push_back(s.vertex_vertices(VertexId{i}));
    }
    shared.origins = s.triangle_origins();
    const Shared &view = shared;
    const std::uint64_t want_relations = relations(s, v), want_ranges = ranges(view);
    std::vector<int> failed(8, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 8; t++)
        threads.emplace_back([&, t] {
            for (int r = 0; r < rounds; r++) {
                // Half the threads start with the ranges, half with the relations.
                bool ok = t % 2 ? ranges(view) == want_ranges && relations(s, v) == want_relations
                                : relations(s, v) == want_relations && ranges(view) == want_ranges;
                if (!ok) failed[t] = 1;
            }
        });
    for (auto &th : threads) th.join();
    int bad = 0;
    for (int t = 0; t < 8; t++)
        if (failed[t]) std::fprintf(stderr, "thread %d: answers differ from one thread's\n", t), bad++;
    if (bad) return 1;
    std::printf("test_stress_cpp: 8 threads x %d rounds agree (grid %u)\n", rounds, g);
    return 0;
}
