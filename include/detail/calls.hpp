// topomesh C++ wrapper, implementation: the uniform shapes of a C call (an id relation into
// a buffer, one value, one flag, a zero-copy view, a CSR pair), shared by Surface (che_mesh)
// and Volume (chf_mesh), and the status check that turns a failure into topomesh::Error.
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_CALLS_HPP
#define TOPOMESH_DETAIL_CALLS_HPP

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>

namespace topomesh {

struct Csr;

namespace detail {

/// Throws topomesh::Error with the status and the detail of the last failure on this
/// thread (defined in detail/error.hpp, after Error).
[[noreturn]] inline void throw_error(topomesh_status s);
/// Throws topomesh::Error with the status and this detail.
[[noreturn]] inline void throw_error(topomesh_status s, const std::string &detail);

/// Throws Error unless `s` is OK.
inline void check(topomesh_status s) {
    if (s != TOPOMESH_STATUS_OK) throw_error(s);
}

/// The C call shapes over a handle type M (che_mesh or chf_mesh).
template <class M> struct Calls {
    using RelationFn = topomesh_status (*)(const M *, std::uint32_t, std::uint32_t *,
                                           std::size_t, std::size_t *);
    using ValueFn = topomesh_status (*)(const M *, std::uint32_t, std::uint32_t *);
    using FlagFn = topomesh_status (*)(const M *, std::uint32_t, bool *);
    using ViewFn = const std::uint32_t *(*)(const M *, std::size_t *);
    using CsrFn = topomesh_status (*)(const M *, std::uint32_t *, std::size_t,
                                      std::uint32_t *, std::size_t, std::size_t *,
                                      std::size_t *);
};

/// Writes into an Ids (a friend of it).
struct IdsWriter {
    template <class Ids> static void push(Ids &out, std::uint32_t id) { out.push_raw(id); }
    /// Sets the ids of an empty Ids to `ids` (at most its inline capacity). One store per
    /// id, no initializer_list: a fixed-size answer then stays in registers, and a loop over
    /// it unrolls at -O2 as over a std::array.
    template <class Ids, class... U> static void set(Ids &out, U... ids) {
        std::uint32_t *buf = out.buffer(0);
        std::size_t i = 0;
        ((buf[i++] = static_cast<std::uint32_t>(ids)), ...);
        out.size_ = sizeof...(U);
    }
    /// One call into the inline buffer; a second into the heap when the answer is longer.
    template <class Ids, class M, class F>
    static void call(Ids &out, F f, const M *m, std::uint32_t id) {
        std::size_t len = 0;
        std::uint32_t *buf = out.buffer(0);
        topomesh_status s = f(m, id, buf, Ids::inline_capacity(), &len);
        if (Ids::grows && s == TOPOMESH_STATUS_BUFFER_TOO_SMALL) {
            buf = out.buffer(len);
            s = f(m, id, buf, len, &len);
        }
        check(s);
        out.size_ = len;
    }
    /// `call` for the relations whose answer always has exactly N ids (a triangle's three
    /// vertices, edges and neighbours; an edge's two vertices). The C call writes into a
    /// local array, not into `out`, so that `out` never escapes: for the same reason as
    /// `set`, a loop over the answer then unrolls as over a std::array.
    template <class Ids, class M, class F>
    static void call_exact(Ids &out, F f, const M *m, std::uint32_t id) {
        constexpr std::size_t n = Ids::inline_capacity();
        std::uint32_t ids[n];
        std::size_t len = 0;
        check(f(m, id, ids, n, &len));
        if (len != n) throw std::logic_error("topomesh: a fixed-size answer of another size");
        std::uint32_t *buf = out.buffer(0);
        for (std::size_t i = 0; i < n; i++) buf[i] = ids[i];
        out.size_ = n;
    }
};

/// The ids of relation `f` of element `id`.
template <class Ids, class M>
Ids relation(typename Calls<M>::RelationFn f, const M *m, std::uint32_t id) {
    Ids out;
    IdsWriter::call(out, f, m, id);
    return out;
}

template <class M> std::uint32_t value(typename Calls<M>::ValueFn f, const M *m, std::uint32_t id) {
    std::uint32_t out = TOPOMESH_NONE;
    check(f(m, id, &out));
    return out;
}

template <class M> bool flag(typename Calls<M>::FlagFn f, const M *m, std::uint32_t id) {
    bool out = false;
    check(f(m, id, &out));
    return out;
}

/// A zero-copy view; empty when the level does not store it.
template <class M> Span<std::uint32_t> view(typename Calls<M>::ViewFn f, const M *m) {
    std::size_t len = 0;
    const std::uint32_t *p = f(m, &len);
    return Span<std::uint32_t>(p, p ? len : 0);
}

/// A bulk relation: one call for the sizes, one to fill (defined with Csr).
template <class M> Csr csr(typename Calls<M>::CsrFn f, const M *m);

/// The vector form of a flat element array: `ids.size()` a multiple of `arity`, and
/// `positions` empty or 3 per vertex; throws INVALID_INPUT otherwise.
inline void check_arrays(std::size_t ids, std::size_t arity, const char *what, std::size_t positions,
                  std::size_t n_vertices);

/// The C build options of `options`, from the C defaults so that a field the C struct adds
/// keeps its default.
inline che_build_options che_options(const Options &options) noexcept {
    che_build_options o = che_build_options_default();
    o.level = options.level;
    o.strict = options.strict;
    o.threads = options.threads;
    o.memory_limit_bytes = options.memory_limit_bytes;
    o.weld_tolerance = options.weld_tolerance;
    return o;
}
inline chf_build_options chf_options(const Options &options) noexcept {
    chf_build_options o = chf_build_options_default();
    o.level = options.level;
    o.strict = options.strict;
    o.threads = options.threads;
    o.memory_limit_bytes = options.memory_limit_bytes;
    o.weld_tolerance = options.weld_tolerance;
    return o;
}

} // namespace detail
} // namespace topomesh

#endif // TOPOMESH_DETAIL_CALLS_HPP
