// topomesh C++ wrapper, implementation: turning a failed status into topomesh::Error, and
// the CSR call shape (both need types that topomesh.hpp defines after the classes).
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_ERROR_HPP
#define TOPOMESH_DETAIL_ERROR_HPP

#include <cstddef>
#include <cstdint>
#include <string>

namespace topomesh {
namespace detail {

/// The detail of the last failure on this thread.
inline std::string last_error() {
    std::size_t len = 0;
    if (topomesh_last_error(nullptr, 0, &len) != TOPOMESH_STATUS_OK || len == 0) return {};
    std::string s(len, '\0');
    if (topomesh_last_error(&s[0], s.size(), &len) != TOPOMESH_STATUS_OK) return {};
    s.resize(len - 1);
    return s;
}

[[noreturn]] inline void throw_error(topomesh_status s) { throw Error(s, last_error()); }

[[noreturn]] inline void throw_error(topomesh_status s, const std::string &detail) {
    throw Error(s, detail);
}

inline void check_arrays(std::size_t ids, std::size_t arity, const char *what,
                         std::size_t positions, std::size_t n_vertices) {
    if (ids % arity != 0)
        throw_error(TOPOMESH_STATUS_INVALID_INPUT, std::string(what) + " array has " +
                                                       std::to_string(ids) + " ids, not a multiple of " +
                                                       std::to_string(arity));
    if (positions != 0 && positions != 3 * n_vertices)
        throw_error(TOPOMESH_STATUS_INVALID_INPUT,
                    std::to_string(positions) + " coordinates given for " +
                        std::to_string(n_vertices) + " vertices");
}

template <class M> Csr csr(typename Calls<M>::CsrFn f, const M *m) {
    std::size_t n_offsets = 0, n_indices = 0;
    check(f(m, nullptr, 0, nullptr, 0, &n_offsets, &n_indices));
    Csr out;
    out.offsets.resize(n_offsets);
    out.indices.resize(n_indices);
    // A NULL data() of an empty vector is fine: the capacities say 0 is enough.
    std::uint32_t dummy = 0;
    check(f(m, out.offsets.empty() ? &dummy : out.offsets.data(), n_offsets,
            out.indices.empty() ? &dummy : out.indices.data(), n_indices, &n_offsets,
            &n_indices));
    return out;
}

} // namespace detail
} // namespace topomesh

#endif // TOPOMESH_DETAIL_ERROR_HPP
