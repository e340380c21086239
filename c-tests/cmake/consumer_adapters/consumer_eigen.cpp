// The adapter consumer of the packaging tests: a square of two triangles as libigl's V and
// F and its Laplacian as an Eigen sparse matrix. Prints one line the test checks.
#include <topomesh/eigen.hpp>

#include <cstdio>
#include <vector>

int main() {
    std::vector<std::uint32_t> tris{0, 1, 2, 0, 2, 3};
    std::vector<double> pos{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    topomesh::Surface s = topomesh::Surface::from_triangles(tris, 4, pos);
    const Eigen::MatrixXd V = topomesh::eigen::vertices(s);
    const Eigen::MatrixXi F = topomesh::eigen::triangles(s);
    const auto L = topomesh::eigen::sparse(s.matrix(CHE_MATRIX_KIND_LAPLACIAN));
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(L.cols());
    std::printf("consumer_eigen: V %dx%d, F %dx%d, laplacian %dx%d with %d entries\n",
                int(V.rows()), int(V.cols()), int(F.rows()), int(F.cols()), int(L.rows()),
                int(L.cols()), int(L.nonZeros()));
    return (L * ones).norm() == 0.0 && V(2, 1) == 1.0 ? 0 : 1;
}
