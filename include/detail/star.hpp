// topomesh C++ wrapper, implementation: stars of a surface vertex.
//
// StarRange iterates the rotation with the C API's stack iterator (che_star_begin, then
// che_star_next, inline from level 2): every iterator holds its own che_star_iter, so
// iterators of one range, and one const range shared by threads, never share state.
// The vertex relations of a Surface fill an Ids: from level 2 the ones that need no edge id
// walk V, O and VH inline (no call into the library), the rotation being the one of
// che_star_next in topomesh_inline.h.
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_STAR_HPP
#define TOPOMESH_DETAIL_STAR_HPP

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace topomesh {
namespace detail {

/// The zero-copy arrays of a Surface's level (NULL where the level stores none) and its
/// counts: what the inline paths read. Fetched when the Surface gets its handle and when
/// its level changes.
struct SurfaceViews {
    const std::uint32_t *V = nullptr;  // from level 0
    const std::uint32_t *O = nullptr;  // from level 1
    const std::uint32_t *VH = nullptr; // from level 2
    const std::uint32_t *EH = nullptr; // from level 2
    const double *P = nullptr;         // the positions, x y z per vertex, when built with them
    std::uint32_t nv = 0, nt = 0, ne = 0;

    void fetch(const che_mesh *m) noexcept {
        che_views all;
        // One call (every edit fetches again); a NULL handle gives no views and no call
        // that would record a NULL_ARGUMENT detail.
        if (m == nullptr || che_mesh_views(m, &all) != TOPOMESH_STATUS_OK) {
            *this = SurfaceViews{};
            return;
        }
        V = all.half_edge_vertices;
        O = all.opposites;
        VH = all.vertex_half_edges;
        EH = all.edge_half_edges;
        P = all.positions;
        nv = static_cast<std::uint32_t>(all.num_vertices);
        nt = static_cast<std::uint32_t>(all.num_triangles);
        ne = static_cast<std::uint32_t>(all.num_edges);
    }
    bool vertex(std::uint32_t v) const noexcept { return v < nv; }
    bool triangle(std::uint32_t t) const noexcept { return t < nt; }
    bool edge(std::uint32_t e) const noexcept { return e < ne; }
    bool half_edge(std::uint32_t h) const noexcept { return h / 3u < nt; }
    /// The star of v can be walked inline (level 2 or more, v in range).
    bool star(std::uint32_t v) const noexcept { return VH != nullptr && v < nv; }
};

/// What a vertex relation keeps of each step of the inline walk.
enum class StarPart { vertex, triangle };

/// The rotation around v (which views.star(v) accepts) as che_star_next walks it,
/// counter-clockwise from the boundary: for each triangle its outgoing half-edge's target
/// or its triangle, then, for a vertex relation on a boundary vertex, the closing
/// half-edge's origin. Appends to `out`.
template <StarPart Part, class Ids>
void walk_star(const SurfaceViews &views, std::uint32_t v, Ids &out) {
    const std::uint32_t *const V = views.V, *const O = views.O;
    const std::uint32_t start = views.VH[v];
    std::uint32_t cur = start, tail = TOPOMESH_NONE;
    while (cur != TOPOMESH_NONE) {
        const std::uint32_t h = cur, p = che_prev(h), g = O[p];
        cur = (g == TOPOMESH_NONE || g == start) ? TOPOMESH_NONE : g;
        if (g == TOPOMESH_NONE) tail = p;
        IdsWriter::push(out, Part == StarPart::vertex ? V[che_next(h)] : che_tri(h));
    }
    if (Part == StarPart::vertex && tail != TOPOMESH_NONE) IdsWriter::push(out, V[tail]);
}

} // namespace detail

/// The star of a vertex as a range of StarStep (see Surface::star). An input range: each
/// begin() starts a walk of its own, and any number of iterators (of one range, in one
/// thread or several) walk independently.
class StarRange {
public:
    using value_type = StarStep;
    struct Sentinel {};

    class Iterator {
    public:
        using iterator_category = std::input_iterator_tag;
        using value_type = StarStep;
        using difference_type = std::ptrdiff_t;
        using pointer = const StarStep *;
        using reference = const StarStep &;

        const StarStep &operator*() const noexcept { return current_; }
        const StarStep *operator->() const noexcept { return &current_; }
        Iterator &operator++() {
            advance();
            return *this;
        }
        void operator++(int) { advance(); }
        friend bool operator==(const Iterator &it, Sentinel) noexcept { return it.done_; }
        friend bool operator!=(const Iterator &it, Sentinel) noexcept { return !it.done_; }
        friend bool operator==(Sentinel, const Iterator &it) noexcept { return it.done_; }
        friend bool operator!=(Sentinel, const Iterator &it) noexcept { return !it.done_; }

    private:
        friend class StarRange;
        Iterator(const che_mesh *m, VertexId v) {
            detail::check(che_star_begin(m, v.value(), &c_));
            advance();
        }
        void advance() {
            che_star_step s;
            if (!che_star_next(&c_, &s)) {
                done_ = true;
                return;
            }
            current_ = StarStep{HalfEdgeId{s.half_edge}, VertexId{s.vertex}, EdgeId{s.edge},
                                TriangleId{s.triangle}};
        }
        che_star_iter c_{}; // this iterator's own state of the C rotation
        StarStep current_{};
        bool done_ = false;
    };

    StarRange(const che_mesh *m, VertexId v) noexcept : m_(m), v_(v) {}
    /// Throws Error when the vertex is out of range.
    Iterator begin() const { return Iterator(m_, v_); }
    Sentinel end() const noexcept { return {}; }

    /// The whole range as a vector.
    std::vector<StarStep> to_vector() const {
        std::vector<StarStep> out;
        for (auto it = begin(); it != end(); ++it) out.push_back(*it);
        return out;
    }

private:
    const che_mesh *m_;
    VertexId v_;
};

} // namespace topomesh

#endif // TOPOMESH_DETAIL_STAR_HPP
