// The same with the C++ wrapper: build, write the repaired mesh, read it back.
#include <topomesh/topomesh.hpp>
#include <iostream>

int main() {
    using namespace topomesh;
    // A tetrahedron's surface whose last triangle is reversed.
    Surface s = Surface::from_triangles({0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 2, 3}, 4,
                                        {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
    s.write("repaired.ply", TOPOMESH_WRITE_BINARY);
    Surface back = Surface::load("repaired.ply");
    std::cout << "flipped " << s.report().flipped_triangles
              << " triangle(s); repaired.ply: flipped " << back.report().flipped_triangles
              << '\n';
    return 0;
}
