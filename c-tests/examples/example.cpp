// The same with the C++17 wrapper: RAII, strong ids, ranges, exceptions.
#include <topomesh/topomesh.hpp>
#include <iostream>

int main() {
    using namespace topomesh;
    Surface s = Surface::from_triangles({0, 1, 2, 1, 3, 2}, 4, {}, {/*level*/ 2});

    std::cout << "around vertex 1:";
    for (VertexId w : s.vertex_vertices(VertexId{1})) std::cout << ' ' << w.value();
    std::cout << '\n';

    for (const StarStep &step : s.star(VertexId{2}))
        std::cout << "vertex 2 -> " << step.vertex.value() << " (edge " << step.edge.value()
                  << (step.closing() ? ") closes the boundary fan\n" : ")\n");

    Span<std::uint32_t> V = s.half_edge_vertices(), O = s.opposites();
    for (std::uint32_t h = 0; h < V.size(); h++)
        if (O[h] == none) std::cout << "boundary " << V[h] << " -> " << V[che_next(h)] << '\n';

    Surface::Summary sum = s.summary();
    std::cout << "euler=" << sum.euler_characteristic << " genus=" << sum.genus << '\n';

    try {
        s.triangle_vertices(TriangleId{7});
    } catch (const Error &e) {
        std::cout << "error: " << e.what() << '\n'; // out of range: triangle 7 out of range ...
    }
    return 0;
}
