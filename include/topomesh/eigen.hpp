// <topomesh/eigen.hpp>: topomesh meshes and exported matrices as Eigen matrices, in
// libigl's conventions (header-only; include it only where Eigen is found, e.g. through
// the CMake package's Eigen component).
//
//   Eigen::MatrixXd V = topomesh::eigen::vertices(s);   // #V x 3, one vertex per row
//   Eigen::MatrixXi F = topomesh::eigen::triangles(s);  // #F x 3, counter-clockwise
//   auto L = topomesh::eigen::sparse(s.matrix(CHE_MATRIX_KIND_LAPLACIAN));
//
// The sparse matrices are copies into Eigen's own compressed row storage (one pass over
// the entries, no triplets): a CsrMatrix keeps 64-bit offsets and 32-bit columns, and an
// Eigen::Map needs one index type for both.
#ifndef TOPOMESH_EIGEN_HPP
#define TOPOMESH_EIGEN_HPP

#include "topomesh.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <cstdint>
#include <limits>

namespace topomesh {
namespace eigen {

/// The positions as libigl's V: one row x, y, z per vertex of the structure (split copies
/// included); throws Error when the mesh has no positions.
template <class Mesh> Eigen::MatrixXd vertices(const Mesh &m) {
    const Span<double> p = m.positions();
    if (p.empty() && m.num_vertices() != 0)
        detail::throw_error(TOPOMESH_STATUS_INVALID_INPUT, "eigen::vertices: no positions");
    Eigen::MatrixXd V(Eigen::Index(m.num_vertices()), 3);
    for (std::size_t v = 0; v < m.num_vertices(); v++)
        for (int k = 0; k < 3; k++) V(Eigen::Index(v), k) = p[3 * v + std::size_t(k)];
    return V;
}

/// The triangles as libigl's F: row t the vertices of triangle t, counter-clockwise seen
/// from outside (CHE's V array, 3t .. 3t + 2).
inline Eigen::MatrixXi triangles(const Surface &s) {
    const std::vector<std::uint32_t> v = s.halfedge().vertex;
    Eigen::MatrixXi F(Eigen::Index(s.num_triangles()), 3);
    for (std::size_t t = 0; t < s.num_triangles(); t++)
        for (int k = 0; k < 3; k++) F(Eigen::Index(t), k) = int(v[3 * t + std::size_t(k)]);
    return F;
}

/// The tetrahedra as libigl's T: row t the four vertices of tetrahedron t.
inline Eigen::MatrixXi tetrahedra(const Volume &vol) {
    Eigen::MatrixXi T(Eigen::Index(vol.num_tetrahedra()), 4);
    for (TetrahedronId t : vol.tetrahedra()) {
        auto c = vol.tetrahedron_vertices(t);
        for (int k = 0; k < 4; k++) T(Eigen::Index(t.value()), k) = int(c[std::size_t(k)].value());
    }
    return T;
}

/// An exported matrix as an Eigen sparse matrix (row-major, compressed, `Index` its index
/// type); throws Error when an offset does not fit `Index`.
template <class Index = int>
Eigen::SparseMatrix<double, Eigen::RowMajor, Index> sparse(const CsrMatrix &a) {
    if (a.nonzeros() > std::uint64_t(std::numeric_limits<Index>::max()) ||
        a.cols > std::uint64_t(std::numeric_limits<Index>::max()))
        detail::throw_error(TOPOMESH_STATUS_INVALID_INPUT,
                            "eigen::sparse: " + std::to_string(a.nonzeros()) +
                                " entries do not fit the index type");
    Eigen::SparseMatrix<double, Eigen::RowMajor, Index> out(Eigen::Index(a.rows),
                                                             Eigen::Index(a.cols));
    out.resizeNonZeros(Eigen::Index(a.nonzeros()));
    for (std::size_t r = 0; r <= a.rows; r++) out.outerIndexPtr()[r] = Index(a.offsets[r]);
    for (std::size_t i = 0; i < a.nonzeros(); i++) {
        out.innerIndexPtr()[i] = Index(a.columns[i]);
        out.valuePtr()[i] = a.values[i];
    }
    out.finalize();
    return out;
}

} // namespace eigen
} // namespace topomesh

#endif // TOPOMESH_EIGEN_HPP
