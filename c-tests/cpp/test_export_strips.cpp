// Surface::strips() beside meshoptimizer's meshopt_stripify on real meshes:
//
//   test_export_strips MESH.off...
//
// Both stripifiers get the same triangles (the CHE's V array, so that meshoptimizer sees
// the split, oriented surface topomesh strips); meshoptimizer as its documentation
// advises, after meshopt_optimizeVertexCacheStrip (its strips follow the triangle order,
// which it needs to be cache-friendly). Both outputs must stand for exactly those
// triangles, each once in its orientation, with restarts and joined by degenerate
// triangles; the strip and index counts of both are printed, and topomesh's index count
// must stay within a quarter of meshoptimizer's (the benchmarks hold the closer target).
#include "check.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <vector>

using namespace topomesh;

using Tri = std::array<std::uint32_t, 3>;

// The triangles of a strip list (restart marker `restart`, or none when joined), the
// degenerate ones dropped, each rotated to start at its smallest vertex, sorted.
static std::vector<Tri> decode(const std::vector<std::uint32_t> &l, std::uint32_t restart) {
    std::vector<Tri> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= l.size(); i++) {
        if (i < l.size() && l[i] != restart) continue;
        for (std::size_t k = start; k + 2 < i; k++) {
            Tri t = (k - start) % 2 == 0 ? Tri{l[k], l[k + 1], l[k + 2]} : Tri{l[k + 1], l[k], l[k + 2]};
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            out.push_back(t);
        }
        start = i + 1;
    }
    std::sort(out.begin(), out.end());
    return out;
}

static std::vector<std::uint32_t> meshopt(const std::vector<std::uint32_t> &idx, std::size_t nv,
                                          std::uint32_t restart) {
    std::vector<std::uint32_t> out(meshopt_stripifyBound(idx.size()));
    out.resize(meshopt_stripify(out.data(), idx.data(), idx.size(), nv, restart));
    return out;
}

static void one_mesh(const char *path) {
    const Surface s = Surface::load(path);
    const std::vector<std::uint32_t> v = s.halfedge().vertex;
    std::vector<Tri> want;
    for (std::size_t t = 0; 3 * t < v.size(); t++) {
        Tri a{v[3 * t], v[3 * t + 1], v[3 * t + 2]};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        want.push_back(a);
    }
    std::sort(want.begin(), want.end());
    const std::vector<std::uint32_t> ours = s.strips(StripList::restarts),
                                     ours_joined = s.strips(StripList::joined);
    std::vector<std::uint32_t> ordered(v.size());
    meshopt_optimizeVertexCacheStrip(ordered.data(), v.data(), v.size(), s.num_vertices());
    const std::vector<std::uint32_t> theirs = meshopt(ordered, s.num_vertices(), ~0u),
                                     theirs_joined = meshopt(ordered, s.num_vertices(), 0);
    CHECK(decode(ours, none) == want);
    CHECK(decode(ours_joined, none) == want);
    CHECK(decode(theirs, ~0u) == want);
    CHECK(decode(theirs_joined, none) == want);
    auto strips = [](const std::vector<std::uint32_t> &l) {
        return l.empty() ? 0 : 1 + std::size_t(std::count(l.begin(), l.end(), none));
    };
    std::printf("%s: %zu triangles; strips topomesh %zu, meshoptimizer %zu; indices with restarts "
                "topomesh %zu, meshoptimizer %zu; joined topomesh %zu, meshoptimizer %zu\n",
                path, want.size(), strips(ours), strips(theirs), ours.size(), theirs.size(),
                ours_joined.size(), theirs_joined.size());
    CHECK(4 * ours.size() <= 5 * theirs.size());
    CHECK(4 * ours_joined.size() <= 5 * theirs_joined.size());
}

int main(int argc, char **argv) {
    return run_tests("test_export_strips", [&] {
        for (int i = 1; i < argc; i++) one_mesh(argv[i]);
    });
}
