// The C++ consumer of the packaging tests: a square of two triangles through the wrapper,
// by the element ranges, position(v) and per-vertex data. Prints one line the test checks.
#include <topomesh/topomesh.hpp>

#include <cstdio>
#include <vector>

#if __cplusplus < 201703L
#error "the topomesh targets must bring C++17 (cxx_std_17)"
#endif

int main() {
    std::vector<std::uint32_t> tris{0, 1, 2, 0, 2, 3};
    std::vector<double> pos{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    topomesh::Surface s = topomesh::Surface::from_triangles(tris, 4, pos);
    topomesh::VertexData<double> x(s, 0.0);
    double sum = 0;
    for (topomesh::VertexId v : s.vertices()) {
        x[v] = s.position(v).x;
        sum += x[v] + s.position(v)[1];
    }
    std::printf("consumer: %zu vertices %zu edges %zu curves, sum of x+y %g\n",
                s.vertices().size(), s.edges().size(), s.boundary_curves().size(), sum);
    return sum == 4.0 ? 0 : 1;
}
