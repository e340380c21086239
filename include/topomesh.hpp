// topomesh: header-only C++17 wrapper over the C API (topomesh.h).
//
//   topomesh::Surface s = topomesh::Surface::load("bunny.off");
//   for (topomesh::VertexId w : s.vertices_around(topomesh::VertexId{0})) { ... }
//
//   topomesh::Volume vol = topomesh::Volume::load("box.mesh");
//   for (topomesh::TetrahedronId t : vol.vertex_tetrahedra(topomesh::VertexId{0})) { ... }
//   topomesh::Surface skin = vol.boundary();
//
// - topomesh::Surface owns a che_mesh, topomesh::Volume a chf_mesh (move-only RAII); every
//   failing call throws topomesh::Error (a std::runtime_error carrying the status and the
//   detail).
// - Ids are strong types (VertexId, EdgeId, TriangleId, HalfEdgeId; FaceId, TetrahedronId,
//   HalfFaceId for volumes); an invalid id (TOPOMESH_NONE) has valid() == false.
// - Surface stars are ranges with no allocation; a Surface keeps the zero-copy arrays of
//   its level (V, O, VH, EH) and its ranges and fixed-size relations step inline over
//   them, with the range checks of the C API (a failing id goes through the C call, which
//   reports it); what the level does not store goes through the C API. Volume relations
//   around a vertex or an edge return an IdList (a std::vector of ids); the bounded ones
//   a std::array or a SmallIds.
// - Views are Span<T> (pointer + size) into the structure, valid until the mesh is
//   destroyed or its level changes.
// - Thread safety is the C API's: const member functions may run concurrently;
//   build_level() and destruction need exclusive access.
#ifndef TOPOMESH_HPP
#define TOPOMESH_HPP

#include "topomesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace topomesh {

/// No element: boundary, none, invalid.
inline constexpr std::uint32_t none = TOPOMESH_NONE;

/// A failed call: the status and the detail of topomesh_last_error().
class Error : public std::runtime_error {
public:
    Error(topomesh_status status, const std::string &detail)
        : std::runtime_error(std::string(topomesh_status_str(status)) + ": " + detail),
          status_(status), detail_(detail) {}
    topomesh_status status() const noexcept { return status_; }
    const std::string &detail() const noexcept { return detail_; }

private:
    topomesh_status status_;
    std::string detail_;
};

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

/// Throws Error unless `s` is OK.
inline void check(topomesh_status s) {
    if (s != TOPOMESH_STATUS_OK) throw Error(s, last_error());
}

} // namespace detail

/// A strongly typed id; `Tag` keeps vertex, edge, triangle and half-edge ids apart.
template <class Tag> class Id {
public:
    constexpr Id() noexcept = default;
    constexpr explicit Id(std::uint32_t value) noexcept : value_(value) {}
    constexpr std::uint32_t value() const noexcept { return value_; }
    constexpr bool valid() const noexcept { return value_ != none; }
    friend constexpr bool operator==(Id a, Id b) noexcept { return a.value_ == b.value_; }
    friend constexpr bool operator!=(Id a, Id b) noexcept { return a.value_ != b.value_; }
    friend constexpr bool operator<(Id a, Id b) noexcept { return a.value_ < b.value_; }

private:
    std::uint32_t value_ = none;
};

using VertexId = Id<struct VertexTag>;
using EdgeId = Id<struct EdgeTag>;
using TriangleId = Id<struct TriangleTag>;
using HalfEdgeId = Id<struct HalfEdgeTag>;

/// Half-edge arithmetic (all levels): triangle t owns half-edges 3t, 3t+1, 3t+2.
constexpr TriangleId triangle_of(HalfEdgeId h) noexcept { return TriangleId{h.value() / 3u}; }
constexpr HalfEdgeId next(HalfEdgeId h) noexcept {
    return HalfEdgeId{h.value() % 3u == 2u ? h.value() - 2u : h.value() + 1u};
}
constexpr HalfEdgeId prev(HalfEdgeId h) noexcept {
    return HalfEdgeId{h.value() % 3u == 0u ? h.value() + 2u : h.value() - 1u};
}
constexpr HalfEdgeId first_half_edge(TriangleId t) noexcept { return HalfEdgeId{3u * t.value()}; }

using FaceId = Id<struct FaceTag>;
using TetrahedronId = Id<struct TetrahedronTag>;
using HalfFaceId = Id<struct HalfFaceTag>;

/// Half-face arithmetic (all levels): tetrahedron t owns half-faces 4t .. 4t+3; half-face
/// 4t + i is the face opposite local vertex i.
constexpr TetrahedronId tetrahedron_of(HalfFaceId hf) noexcept {
    return TetrahedronId{hf.value() >> 2};
}
constexpr std::uint32_t local_index(HalfFaceId hf) noexcept { return hf.value() & 3u; }
constexpr HalfFaceId next(HalfFaceId hf) noexcept {
    return HalfFaceId{(hf.value() & ~3u) | ((hf.value() + 1u) & 3u)};
}
constexpr HalfFaceId first_half_face(TetrahedronId t) noexcept {
    return HalfFaceId{4u * t.value()};
}
/// The half-face whose V entry is corner j (0..2) of `hf` in its outward order.
constexpr HalfFaceId face_corner(HalfFaceId hf, std::uint32_t j) noexcept {
    return HalfFaceId{(hf.value() & ~3u) |
                      ((0x634B39u >> (2u * (3u * (hf.value() & 3u) + j))) & 3u)};
}

/// A read-only view: pointer + size (C++17 has no std::span).
template <class T> class Span {
public:
    using value_type = T;
    using iterator = const T *;
    constexpr Span() noexcept = default;
    constexpr Span(const T *data, std::size_t size) noexcept : data_(data), size_(size) {}
    constexpr const T *data() const noexcept { return data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr bool empty() const noexcept { return size_ == 0; }
    constexpr const T *begin() const noexcept { return data_; }
    constexpr const T *end() const noexcept { return data_ + size_; }
    constexpr const T &operator[](std::size_t i) const noexcept { return data_[i]; }
    const T &at(std::size_t i) const {
        if (i >= size_) throw std::out_of_range("topomesh::Span::at");
        return data_[i];
    }
    std::vector<T> to_vector() const { return std::vector<T>(begin(), end()); }

private:
    const T *data_ = nullptr;
    std::size_t size_ = 0;
};

/// Up to N ids without allocation (edge triangles, edge wings).
template <class T, std::size_t N> class SmallIds {
public:
    const T *begin() const noexcept { return ids_.data(); }
    const T *end() const noexcept { return ids_.data() + size_; }
    std::size_t size() const noexcept { return size_; }
    bool empty() const noexcept { return size_ == 0; }
    const T &operator[](std::size_t i) const noexcept { return ids_[i]; }
    void push_back(T id) noexcept { ids_[size_++] = id; }

private:
    std::array<T, N> ids_{};
    std::size_t size_ = 0;
};

/// One step of a rotation around a vertex v (see che_star_step): the outgoing half-edge
/// v -> vertex, its edge and triangle; on a boundary vertex, a last step for the incoming
/// boundary half-edge (vertex -> v) with an invalid triangle.
struct StarStep {
    HalfEdgeId half_edge;
    VertexId vertex;
    EdgeId edge;
    TriangleId triangle;
    /// The closing step of a boundary vertex (no triangle).
    bool closing() const noexcept { return !triangle.valid(); }
};

namespace detail {

/// The zero-copy arrays of a Surface's level (NULL where the level stores none) and its
/// counts: what the inline paths read. Fetched when the Surface gets its handle and when
/// its level changes.
struct SurfaceViews {
    const std::uint32_t *V = nullptr;  // from level 0
    const std::uint32_t *O = nullptr;  // from level 1
    const std::uint32_t *VH = nullptr; // from level 2
    const std::uint32_t *EH = nullptr; // from level 2
    std::uint32_t nv = 0, nt = 0, ne = 0;

    void fetch(const che_mesh *m) noexcept {
        if (m == nullptr) { // no calls: they would record a NULL_ARGUMENT detail
            *this = SurfaceViews{};
            return;
        }
        V = che_mesh_half_edge_vertices(m, nullptr);
        O = che_mesh_opposites(m, nullptr);
        VH = che_mesh_vertex_half_edges(m, nullptr);
        EH = che_mesh_edge_half_edges(m, nullptr);
        nv = static_cast<std::uint32_t>(che_mesh_num_vertices(m));
        nt = static_cast<std::uint32_t>(che_mesh_num_triangles(m));
        ne = static_cast<std::uint32_t>(che_mesh_num_edges(m));
    }
    bool vertex(std::uint32_t v) const noexcept { return v < nv; }
    bool triangle(std::uint32_t t) const noexcept { return t < nt; }
    bool edge(std::uint32_t e) const noexcept { return e < ne; }
    bool half_edge(std::uint32_t h) const noexcept { return h / 3u < nt; }
};

} // namespace detail

/// A range over the star of a vertex. `Proj` picks what each step yields; steps without a
/// triangle are skipped when `SkipClosing`. From level 2 the steps that need no edge id
/// walk V, O and VH inline (no call into the library at all); the others use the C stack
/// iterator (whose che_star_next is inline from level 2 too).
template <class Proj, bool SkipClosing> class StarRange {
public:
    using value_type = decltype(Proj{}(StarStep{}));

    struct Sentinel {};

    class Iterator {
    public:
        using iterator_category = std::input_iterator_tag;
        using value_type = StarRange::value_type;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = value_type;

        value_type operator*() const {
            if constexpr (!Proj::needs_edge) {
                if (V_ != nullptr) return value_type{batch_[i_]};
            }
            return Proj{}(current_);
        }
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
        // Inline, the walk runs in batches of up to kBatch steps over local variables
        // (the iterator itself lives in memory: stepping it one at a time would put a
        // store and a reload on the rotation's dependency chain); the C iterator's state
        // lives in the range (`c`).
        static constexpr unsigned kBatch = Proj::needs_edge ? 1u : 16u;
        Iterator(const che_mesh *m, const detail::SurfaceViews &views, VertexId v,
                 che_star_iter *c) {
            if constexpr (!Proj::needs_edge) {
                if (views.VH != nullptr && views.vertex(v.value())) {
                    V_ = views.V;
                    O_ = views.O;
                    start_ = cur_ = views.VH[v.value()];
                    refill();
                    return;
                }
            }
            detail::check(che_star_begin(m, v.value(), c));
            c_ = c;
            advance();
        }
        void advance() {
            if (V_ != nullptr) {
                if (++i_ < n_) return;
                if (n_ < kBatch) {
                    done_ = true;
                    return;
                }
                refill();
                return;
            }
            che_star_step s;
            bool more;
            while ((more = che_star_next(c_, &s)) && SkipClosing && s.triangle == none) {
            }
            if (!more) {
                done_ = true;
                return;
            }
            current_ = StarStep{HalfEdgeId{s.half_edge}, VertexId{s.vertex}, EdgeId{s.edge},
                                TriangleId{s.triangle}};
        }
        // The next steps of the same rotation as the library's (counter-clockwise, from the
        // boundary), projected; the edge is not computed (Proj does not read it).
        void refill() {
            if constexpr (!Proj::needs_edge) refill_inline();
        }
        void refill_inline() {
            const std::uint32_t *const V = V_, *const O = O_;
            const std::uint32_t start = start_;
            std::uint32_t cur = cur_, tail = tail_;
            unsigned n = 0;
            while (n < kBatch) {
                if (cur != none) {
                    const std::uint32_t h = cur, p = che_prev(h), g = O[p];
                    cur = (g == none || g == start) ? none : g;
                    if (g == none) tail = p;
                    batch_[n++] = Proj{}(StarStep{HalfEdgeId{h}, VertexId{V[che_next(h)]},
                                                  EdgeId{none}, TriangleId{che_tri(h)}})
                                      .value();
                } else if (!SkipClosing && tail != none) {
                    batch_[n++] = Proj{}(StarStep{HalfEdgeId{tail}, VertexId{V[tail]},
                                                  EdgeId{none}, TriangleId{none}})
                                      .value();
                    tail = none;
                } else {
                    break;
                }
            }
            cur_ = cur;
            tail_ = tail;
            n_ = n;
            i_ = 0;
            done_ = n == 0;
        }
        che_star_iter *c_ = nullptr;
        StarStep current_{};
        bool done_ = false;
        const std::uint32_t *V_ = nullptr;
        const std::uint32_t *O_ = nullptr;
        std::uint32_t start_ = none, cur_ = none, tail_ = none;
        unsigned i_ = 0, n_ = 0;
        std::uint32_t batch_[kBatch]; // raw ids of the inline steps i_ .. n_ - 1
    };

    /// `views` belongs to the Surface the range comes from (a moved-from Surface has none:
    /// its ranges then go through the C API, on the handle they were made with).
    StarRange(const che_mesh *m, const detail::SurfaceViews *views, VertexId v) noexcept
        : m_(m), views_(views), v_(v) {}
    /// Throws Error when the vertex is out of range. A range is walked by one iterator at
    /// a time (an input range: begin() again restarts the walk).
    Iterator begin() const { return Iterator(m_, *views_, v_, &c_); }
    Sentinel end() const noexcept { return {}; }

    /// The whole range as a vector.
    std::vector<value_type> to_vector() const {
        std::vector<value_type> out;
        for (auto it = begin(); it != end(); ++it) out.push_back(*it);
        return out;
    }

private:
    const che_mesh *m_;
    const detail::SurfaceViews *views_;
    VertexId v_;
    mutable che_star_iter c_{}; // the C iterator's state, when the walk is not inline
};

namespace detail {
struct StepOf {
    static constexpr bool needs_edge = true;
    StarStep operator()(const StarStep &s) const noexcept { return s; }
};
struct VertexOf {
    static constexpr bool needs_edge = false;
    VertexId operator()(const StarStep &s) const noexcept { return s.vertex; }
};
struct EdgeOf {
    static constexpr bool needs_edge = true;
    EdgeId operator()(const StarStep &s) const noexcept { return s.edge; }
};
struct TriangleOf {
    static constexpr bool needs_edge = false;
    TriangleId operator()(const StarStep &s) const noexcept { return s.triangle; }
};
} // namespace detail

using Star = StarRange<detail::StepOf, false>;
using VerticesAround = StarRange<detail::VertexOf, false>;
using EdgesAround = StarRange<detail::EdgeOf, false>;
using TrianglesAround = StarRange<detail::TriangleOf, true>;

/// A bulk relation in compressed sparse rows: row i is indices[offsets[i] .. offsets[i+1]].
struct Csr {
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> indices;
    std::size_t rows() const noexcept { return offsets.empty() ? 0 : offsets.size() - 1; }
    Span<std::uint32_t> row(std::size_t i) const {
        return Span<std::uint32_t>(indices.data() + offsets.at(i), offsets.at(i + 1) - offsets[i]);
    }
};

/// Build options: the level (0..3) and strict mode (non-manifold input is an error).
struct Options {
    std::uint32_t level = 2;
    bool strict = false;
    /// Threads for the build (0: as many as the machine runs at once; the mesh is the same
    /// whatever the number).
    std::uint32_t threads = 0;
};

/// A triangle surface in the Compact Half-Edge structure (owns a che_mesh).
class Surface {
public:
    using Options = topomesh::Options;

    /// From a flat triangle array (3 ids per triangle) over `n_vertices` vertices;
    /// `positions` is NULL or 3 doubles per vertex.
    static Surface from_triangles(const std::uint32_t *triangles, std::size_t n_triangles,
                                  std::size_t n_vertices, const double *positions = nullptr,
                                  Options options = {}) {
        che_build_options o{options.level, options.strict, options.threads};
        che_mesh *m = nullptr;
        detail::check(che_mesh_from_triangles_ex(triangles, n_triangles, n_vertices, positions,
                                                 &o, &m));
        return Surface(m);
    }

    /// From vectors: `triangles.size()` a multiple of 3; `positions` empty or 3 per vertex.
    static Surface from_triangles(const std::vector<std::uint32_t> &triangles,
                                  std::size_t n_vertices,
                                  const std::vector<double> &positions = {},
                                  Options options = {}) {
        if (triangles.size() % 3 != 0)
            throw Error(TOPOMESH_STATUS_INVALID_INPUT,
                        "triangle array has " + std::to_string(triangles.size()) +
                            " ids, not a multiple of 3");
        if (!positions.empty() && positions.size() != 3 * n_vertices)
            throw Error(TOPOMESH_STATUS_INVALID_INPUT,
                        std::to_string(positions.size()) + " coordinates given for " +
                            std::to_string(n_vertices) + " vertices");
        return from_triangles(triangles.data(), triangles.size() / 3, n_vertices,
                              positions.empty() ? nullptr : positions.data(), options);
    }

    /// Reads a surface file (.off .obj .ply .stl ...).
    static Surface load(const std::string &path, Options options = {}) {
        che_build_options o{options.level, options.strict, options.threads};
        che_mesh *m = nullptr;
        detail::check(che_mesh_load_ex(path.c_str(), &o, &m));
        return Surface(m);
    }

    /// Takes ownership of a handle from the C API.
    explicit Surface(che_mesh *adopt) noexcept : m_(adopt) { views_.fetch(m_); }
    Surface(const Surface &) = delete;
    Surface &operator=(const Surface &) = delete;
    Surface(Surface &&other) noexcept
        : m_(std::exchange(other.m_, nullptr)), views_(std::exchange(other.views_, {})) {}
    Surface &operator=(Surface &&other) noexcept {
        if (this != &other) {
            che_mesh_free(m_);
            m_ = std::exchange(other.m_, nullptr);
            views_ = std::exchange(other.views_, {});
        }
        return *this;
    }
    ~Surface() { che_mesh_free(m_); }

    const che_mesh *handle() const noexcept { return m_; }
    /// The handle, to pass to the C API. Change its level only with build_level(), or call
    /// refresh() after changing it through the handle: the Surface keeps the zero-copy
    /// arrays of the level it last saw.
    che_mesh *handle() noexcept { return m_; }
    /// Gives up ownership; the caller frees with che_mesh_free.
    che_mesh *release() noexcept {
        views_ = {};
        return std::exchange(m_, nullptr);
    }
    /// Fetches the zero-copy arrays again (after a level change made through handle()).
    void refresh() noexcept { views_.fetch(m_); }

    // Level and counts.
    std::uint32_t level() const noexcept { return che_mesh_level(m_); }
    /// Raises or lowers the level; invalidates views.
    void build_level(std::uint32_t level) {
        const topomesh_status s = che_mesh_build_level(m_, level);
        views_.fetch(m_);
        detail::check(s);
    }
    std::size_t num_vertices() const noexcept { return che_mesh_num_vertices(m_); }
    std::size_t num_input_vertices() const noexcept { return che_mesh_num_input_vertices(m_); }
    std::size_t num_triangles() const noexcept { return che_mesh_num_triangles(m_); }
    std::size_t num_edges() const noexcept { return che_mesh_num_edges(m_); }
    std::size_t num_half_edges() const noexcept { return che_mesh_num_half_edges(m_); }
    std::size_t num_boundary_curves() const noexcept { return che_mesh_num_boundary_curves(m_); }

    // Stars (counter-clockwise seen from outside): inline from level 2, see StarRange.
    Star star(VertexId v) const noexcept { return Star(m_, &views_, v); }
    VerticesAround vertices_around(VertexId v) const noexcept {
        return VerticesAround(m_, &views_, v);
    }
    EdgesAround edges_around(VertexId v) const noexcept { return EdgesAround(m_, &views_, v); }
    TrianglesAround triangles_around(VertexId v) const noexcept {
        return TrianglesAround(m_, &views_, v);
    }

    // Fixed-size relations (inline where the level stores what they read).
    std::array<VertexId, 2> edge_vertices(EdgeId e) const {
        if (views_.EH != nullptr && views_.edge(e.value())) {
            const std::uint32_t h = views_.EH[e.value()];
            return {VertexId{views_.V[h]}, VertexId{views_.V[che_next(h)]}};
        }
        auto ids = fixed<2>(che_edge_vertices, e.value());
        return {VertexId{ids[0]}, VertexId{ids[1]}};
    }
    SmallIds<TriangleId, 2> edge_triangles(EdgeId e) const {
        if (views_.EH != nullptr && views_.edge(e.value())) {
            const std::uint32_t h = views_.EH[e.value()], g = views_.O[h];
            SmallIds<TriangleId, 2> out;
            out.push_back(TriangleId{che_tri(h)});
            if (g != none) out.push_back(TriangleId{che_tri(g)});
            return out;
        }
        return small<TriangleId, 2>(che_edge_triangles, e.value());
    }
    SmallIds<EdgeId, 4> edge_edges(EdgeId e) const {
        return small<EdgeId, 4>(che_edge_edges, e.value());
    }
    std::array<VertexId, 3> triangle_vertices(TriangleId t) const {
        if (views_.V != nullptr && views_.triangle(t.value())) {
            const std::uint32_t *c = views_.V + che_first(t.value());
            return {VertexId{c[0]}, VertexId{c[1]}, VertexId{c[2]}};
        }
        auto ids = fixed<3>(che_triangle_vertices, t.value());
        return {VertexId{ids[0]}, VertexId{ids[1]}, VertexId{ids[2]}};
    }
    std::array<EdgeId, 3> triangle_edges(TriangleId t) const {
        auto ids = fixed<3>(che_triangle_edges, t.value());
        return {EdgeId{ids[0]}, EdgeId{ids[1]}, EdgeId{ids[2]}};
    }
    /// The triangle across each edge; invalid across a boundary edge.
    std::array<TriangleId, 3> triangle_triangles(TriangleId t) const {
        if (views_.O != nullptr && views_.triangle(t.value())) {
            const std::uint32_t *o = views_.O + che_first(t.value());
            return {across(o[0]), across(o[1]), across(o[2])};
        }
        auto ids = fixed<3>(che_triangle_triangles, t.value());
        return {TriangleId{ids[0]}, TriangleId{ids[1]}, TriangleId{ids[2]}};
    }
    /// The vertices of boundary curve `curve`, in order.
    std::vector<VertexId> boundary_curve_vertices(std::uint32_t curve) const {
        std::size_t len = 0;
        detail::check(che_boundary_curve_vertices(m_, curve, nullptr, 0, &len));
        std::vector<std::uint32_t> raw(len);
        detail::check(che_boundary_curve_vertices(m_, curve, raw.data(), raw.size(), &len));
        std::vector<VertexId> out;
        out.reserve(len);
        for (std::uint32_t x : raw) out.emplace_back(x);
        return out;
    }

    // Half-edge helpers and boundary tests.
    HalfEdgeId opposite(HalfEdgeId h) const {
        if (views_.O != nullptr && views_.half_edge(h.value())) return HalfEdgeId{views_.O[h.value()]};
        return HalfEdgeId{value(che_half_edge_opposite, h.value())};
    }
    EdgeId edge(HalfEdgeId h) const { return EdgeId{value(che_half_edge_edge, h.value())}; }
    /// The boundary curve of h, or `none`.
    std::uint32_t curve(HalfEdgeId h) const { return value(che_half_edge_curve, h.value()); }
    HalfEdgeId half_edge(VertexId v) const {
        if (views_.VH != nullptr && views_.vertex(v.value())) return HalfEdgeId{views_.VH[v.value()]};
        return HalfEdgeId{value(che_vertex_half_edge, v.value())};
    }
    HalfEdgeId half_edge(EdgeId e) const {
        if (views_.EH != nullptr && views_.edge(e.value())) return HalfEdgeId{views_.EH[e.value()]};
        return HalfEdgeId{value(che_edge_half_edge, e.value())};
    }
    VertexId origin(HalfEdgeId h) const {
        if (views_.V != nullptr && views_.half_edge(h.value())) return VertexId{views_.V[h.value()]};
        Span<std::uint32_t> v = half_edge_vertices();
        return VertexId{v.at(h.value())};
    }
    VertexId target(HalfEdgeId h) const { return origin(next(h)); }
    bool is_boundary(VertexId v) const {
        if (views_.VH != nullptr && views_.vertex(v.value())) {
            const std::uint32_t h = views_.VH[v.value()];
            return h != none && views_.O[h] == none;
        }
        bool b = false;
        detail::check(che_vertex_is_boundary(m_, v.value(), &b));
        return b;
    }
    bool is_boundary(EdgeId e) const {
        if (views_.EH != nullptr && views_.edge(e.value())) return views_.O[views_.EH[e.value()]] == none;
        bool b = false;
        detail::check(che_edge_is_boundary(m_, e.value(), &b));
        return b;
    }

    // Zero-copy views (empty below the level that stores them).
    Span<std::uint32_t> half_edge_vertices() const { return view(che_mesh_half_edge_vertices); }
    Span<std::uint32_t> opposites() const { return view(che_mesh_opposites); }
    Span<std::uint32_t> vertex_half_edges() const { return view(che_mesh_vertex_half_edges); }
    Span<std::uint32_t> edge_half_edges() const { return view(che_mesh_edge_half_edges); }
    Span<std::uint32_t> curve_half_edges() const { return view(che_mesh_curve_half_edges); }
    Span<std::uint32_t> vertex_origins() const { return view(che_mesh_vertex_origins); }
    Span<std::uint32_t> triangle_origins() const { return view(che_mesh_triangle_origins); }
    /// x, y, z per vertex; empty without positions.
    Span<double> positions() const {
        std::size_t len = 0;
        const double *p = che_mesh_positions(m_, &len);
        return Span<double>(p, p ? len : 0);
    }

    // Bulk relations.
    Csr vertex_vertices_csr() const { return csr(che_mesh_vertex_vertices_csr); }
    Csr vertex_edges_csr() const { return csr(che_mesh_vertex_edges_csr); }
    Csr vertex_triangles_csr() const { return csr(che_mesh_vertex_triangles_csr); }
    Csr triangle_triangles_csr() const { return csr(che_mesh_triangle_triangles_csr); }

    // Summary, build report, memory.
    che_summary summary() const {
        che_summary s{};
        detail::check(che_mesh_summary(m_, &s));
        return s;
    }
    che_build_report report() const {
        che_build_report r{};
        detail::check(che_mesh_report(m_, &r));
        return r;
    }
    std::vector<std::uint32_t> report_examples(che_report_kind kind) const {
        std::size_t len = 0;
        detail::check(che_mesh_report_examples(m_, kind, nullptr, 0, &len));
        std::vector<std::uint32_t> out(len);
        detail::check(che_mesh_report_examples(m_, kind, out.data(), out.size(), &len));
        return out;
    }
    che_memory memory() const {
        che_memory mem{};
        detail::check(che_mesh_memory(m_, &mem));
        return mem;
    }

private:
    using RelationFn = topomesh_status (*)(const che_mesh *, std::uint32_t, std::uint32_t *,
                                           std::size_t, std::size_t *);
    using ValueFn = topomesh_status (*)(const che_mesh *, std::uint32_t, std::uint32_t *);
    using ViewFn = const std::uint32_t *(*)(const che_mesh *, std::size_t *);
    using CsrFn = topomesh_status (*)(const che_mesh *, std::uint32_t *, std::size_t,
                                      std::uint32_t *, std::size_t, std::size_t *,
                                      std::size_t *);

    static TriangleId across(std::uint32_t g) noexcept {
        return TriangleId{g == none ? none : che_tri(g)};
    }
    template <std::size_t N> std::array<std::uint32_t, N> fixed(RelationFn f, std::uint32_t id) const {
        std::array<std::uint32_t, N> ids{};
        std::size_t len = 0;
        detail::check(f(m_, id, ids.data(), N, &len));
        return ids;
    }
    template <class T, std::size_t N> SmallIds<T, N> small(RelationFn f, std::uint32_t id) const {
        std::array<std::uint32_t, N> ids{};
        std::size_t len = 0;
        detail::check(f(m_, id, ids.data(), N, &len));
        SmallIds<T, N> out;
        for (std::size_t i = 0; i < len; i++) out.push_back(T{ids[i]});
        return out;
    }
    std::uint32_t value(ValueFn f, std::uint32_t id) const {
        std::uint32_t out = none;
        detail::check(f(m_, id, &out));
        return out;
    }
    Span<std::uint32_t> view(ViewFn f) const {
        std::size_t len = 0;
        const std::uint32_t *p = f(m_, &len);
        return Span<std::uint32_t>(p, p ? len : 0);
    }
    Csr csr(CsrFn f) const {
        std::size_t n_offsets = 0, n_indices = 0;
        detail::check(f(m_, nullptr, 0, nullptr, 0, &n_offsets, &n_indices));
        Csr out;
        out.offsets.resize(n_offsets);
        out.indices.resize(n_indices);
        // A NULL data() of an empty vector is fine: the capacities say 0 is enough.
        std::uint32_t dummy = 0;
        detail::check(f(m_, out.offsets.empty() ? &dummy : out.offsets.data(), n_offsets,
                        out.indices.empty() ? &dummy : out.indices.data(), n_indices,
                        &n_offsets, &n_indices));
        return out;
    }

    che_mesh *m_ = nullptr;
    detail::SurfaceViews views_;
};

/// The structure's name in the papers.
using Che = Surface;

/// A variable-size answer (around a vertex or an edge): the ids, in the C API's order.
template <class T> using IdList = std::vector<T>;

/// A tetrahedral mesh in the Compact Half-Face structure (owns a chf_mesh).
class Volume {
public:
    using Options = topomesh::Options;

    /// From a flat tetrahedron array (4 ids per tetrahedron) over `n_vertices` vertices;
    /// `positions` is NULL or 3 doubles per vertex.
    static Volume from_tetrahedra(const std::uint32_t *tetrahedra, std::size_t n_tets,
                                  std::size_t n_vertices, const double *positions = nullptr,
                                  Options options = {}) {
        chf_build_options o{options.level, options.strict, options.threads};
        chf_mesh *m = nullptr;
        detail::check(chf_mesh_from_tetrahedra_ex(tetrahedra, n_tets, n_vertices, positions,
                                                  &o, &m));
        return Volume(m);
    }

    /// From vectors: `tetrahedra.size()` a multiple of 4; `positions` empty or 3 per vertex.
    static Volume from_tetrahedra(const std::vector<std::uint32_t> &tetrahedra,
                                  std::size_t n_vertices,
                                  const std::vector<double> &positions = {},
                                  Options options = {}) {
        if (tetrahedra.size() % 4 != 0)
            throw Error(TOPOMESH_STATUS_INVALID_INPUT,
                        "tetrahedron array has " + std::to_string(tetrahedra.size()) +
                            " ids, not a multiple of 4");
        if (!positions.empty() && positions.size() != 3 * n_vertices)
            throw Error(TOPOMESH_STATUS_INVALID_INPUT,
                        std::to_string(positions.size()) + " coordinates given for " +
                            std::to_string(n_vertices) + " vertices");
        return from_tetrahedra(tetrahedra.data(), tetrahedra.size() / 4, n_vertices,
                               positions.empty() ? nullptr : positions.data(), options);
    }

    /// Reads a volume file (.mesh .msh .vtk .node/.ele).
    static Volume load(const std::string &path, Options options = {}) {
        chf_build_options o{options.level, options.strict, options.threads};
        chf_mesh *m = nullptr;
        detail::check(chf_mesh_load_ex(path.c_str(), &o, &m));
        return Volume(m);
    }

    /// Takes ownership of a handle from the C API.
    explicit Volume(chf_mesh *adopt) noexcept : m_(adopt) {}
    Volume(const Volume &) = delete;
    Volume &operator=(const Volume &) = delete;
    Volume(Volume &&other) noexcept : m_(std::exchange(other.m_, nullptr)) {}
    Volume &operator=(Volume &&other) noexcept {
        if (this != &other) {
            chf_mesh_free(m_);
            m_ = std::exchange(other.m_, nullptr);
        }
        return *this;
    }
    ~Volume() { chf_mesh_free(m_); }

    const chf_mesh *handle() const noexcept { return m_; }
    chf_mesh *handle() noexcept { return m_; }
    /// Gives up ownership; the caller frees with chf_mesh_free.
    chf_mesh *release() noexcept { return std::exchange(m_, nullptr); }

    // Level and counts.
    std::uint32_t level() const noexcept { return chf_mesh_level(m_); }
    /// Raises or lowers the level; invalidates views.
    void build_level(std::uint32_t level) { detail::check(chf_mesh_build_level(m_, level)); }
    std::size_t num_vertices() const noexcept { return chf_mesh_num_vertices(m_); }
    std::size_t num_input_vertices() const noexcept { return chf_mesh_num_input_vertices(m_); }
    std::size_t num_tetrahedra() const noexcept { return chf_mesh_num_tetrahedra(m_); }
    std::size_t num_faces() const noexcept { return chf_mesh_num_faces(m_); }
    std::size_t num_edges() const noexcept { return chf_mesh_num_edges(m_); }
    std::size_t num_half_faces() const noexcept { return chf_mesh_num_half_faces(m_); }
    /// Faces with exactly one tetrahedron.
    std::size_t num_boundary_faces() const noexcept { return chf_mesh_num_boundary_faces(m_); }
    /// Unpaired half-faces (boundary faces, non-manifold and seam half-faces): the
    /// triangles of boundary().
    std::size_t num_boundary_triangles() const noexcept {
        return chf_mesh_num_boundary_triangles(m_);
    }
    std::size_t num_non_manifold_half_faces() const noexcept {
        return chf_mesh_num_non_manifold_half_faces(m_);
    }
    std::size_t num_seam_half_faces() const noexcept { return chf_mesh_num_seam_half_faces(m_); }
    /// The vertices of boundary() (before its own split).
    std::size_t num_boundary_vertices() const noexcept {
        return chf_mesh_num_boundary_vertices(m_);
    }
    std::size_t num_boundary_components() const noexcept {
        return chf_mesh_num_boundary_components(m_);
    }

    // Around a vertex (each once, in increasing order) and around an
    // edge (rotation order, from the boundary on a boundary edge).
    IdList<VertexId> vertex_vertices(VertexId v) const {
        return list<VertexId>(chf_vertex_vertices, v.value());
    }
    IdList<EdgeId> vertex_edges(VertexId v) const {
        return list<EdgeId>(chf_vertex_edges, v.value());
    }
    IdList<FaceId> vertex_faces(VertexId v) const {
        return list<FaceId>(chf_vertex_faces, v.value());
    }
    IdList<TetrahedronId> vertex_tetrahedra(VertexId v) const {
        return list<TetrahedronId>(chf_vertex_tetrahedra, v.value());
    }
    IdList<EdgeId> edge_edges(EdgeId e) const { return list<EdgeId>(chf_edge_edges, e.value()); }
    IdList<FaceId> edge_faces(EdgeId e) const { return list<FaceId>(chf_edge_faces, e.value()); }
    IdList<TetrahedronId> edge_tetrahedra(EdgeId e) const {
        return list<TetrahedronId>(chf_edge_tetrahedra, e.value());
    }

    // Bounded relations.
    std::array<VertexId, 2> edge_vertices(EdgeId e) const {
        return fixed<VertexId, 2>(chf_edge_vertices, e.value());
    }
    std::array<VertexId, 3> face_vertices(FaceId f) const {
        return fixed<VertexId, 3>(chf_face_vertices, f.value());
    }
    std::array<EdgeId, 3> face_edges(FaceId f) const {
        return fixed<EdgeId, 3>(chf_face_edges, f.value());
    }
    SmallIds<FaceId, 6> face_faces(FaceId f) const {
        return small<FaceId, 6>(chf_face_faces, f.value());
    }
    SmallIds<TetrahedronId, 2> face_tetrahedra(FaceId f) const {
        return small<TetrahedronId, 2>(chf_face_tetrahedra, f.value());
    }
    std::array<VertexId, 4> tetrahedron_vertices(TetrahedronId t) const {
        return fixed<VertexId, 4>(chf_tetrahedron_vertices, t.value());
    }
    std::array<EdgeId, 6> tetrahedron_edges(TetrahedronId t) const {
        return fixed<EdgeId, 6>(chf_tetrahedron_edges, t.value());
    }
    std::array<FaceId, 4> tetrahedron_faces(TetrahedronId t) const {
        return fixed<FaceId, 4>(chf_tetrahedron_faces, t.value());
    }
    /// The tetrahedron across each face; invalid on the boundary.
    std::array<TetrahedronId, 4> tetrahedron_tetrahedra(TetrahedronId t) const {
        return fixed<TetrahedronId, 4>(chf_tetrahedron_tetrahedra, t.value());
    }

    // Half-face helpers and boundary tests.
    HalfFaceId opposite(HalfFaceId hf) const {
        return HalfFaceId{value(chf_half_face_opposite, hf.value())};
    }
    FaceId face(HalfFaceId hf) const { return FaceId{value(chf_half_face_face, hf.value())}; }
    HalfFaceId half_face(FaceId f) const {
        return HalfFaceId{value(chf_face_half_face, f.value())};
    }
    HalfFaceId half_face(VertexId v) const {
        return HalfFaceId{value(chf_vertex_half_face, v.value())};
    }
    bool is_boundary(VertexId v) const { return flag(chf_vertex_is_boundary, v.value()); }
    bool is_boundary(EdgeId e) const { return flag(chf_edge_is_boundary, e.value()); }
    bool is_boundary(FaceId f) const { return flag(chf_face_is_boundary, f.value()); }

    // The boundary surface and its maps.
    /// The boundary as a new Surface (level 3). Its vertices are the boundary vertices only,
    /// with compact ids: see boundary_vertex() and volume_vertex().
    Surface boundary() const {
        che_mesh *s = nullptr;
        detail::check(chf_mesh_boundary(m_, &s));
        return Surface(s);
    }
    /// The boundary triangle of a half-face or face; invalid when interior.
    TriangleId boundary_triangle(HalfFaceId hf) const {
        return TriangleId{value(chf_half_face_boundary_triangle, hf.value())};
    }
    TriangleId boundary_triangle(FaceId f) const {
        return TriangleId{value(chf_face_boundary_triangle, f.value())};
    }
    HalfFaceId boundary_half_face(TriangleId k) const {
        return HalfFaceId{value(chf_boundary_triangle_half_face, k.value())};
    }
    FaceId boundary_face(TriangleId k) const {
        return FaceId{value(chf_boundary_triangle_face, k.value())};
    }
    /// The boundary component of v, or `none` off the boundary.
    std::uint32_t boundary_component(VertexId v) const {
        return value(chf_vertex_boundary_component, v.value());
    }
    /// The vertex of boundary() that v is, or invalid off the boundary.
    VertexId boundary_vertex(VertexId v) const {
        return VertexId{value(chf_vertex_boundary_vertex, v.value())};
    }
    /// The volume vertex of vertex b of boundary() (copies its split made included).
    VertexId volume_vertex(VertexId b) const {
        return VertexId{value(chf_boundary_vertex_vertex, b.value())};
    }

    // Zero-copy views (empty below the level that stores them).
    Span<std::uint32_t> half_face_vertices() const { return view(chf_mesh_half_face_vertices); }
    Span<std::uint32_t> opposites() const { return view(chf_mesh_opposites); }
    Span<std::uint32_t> vertex_half_faces() const { return view(chf_mesh_vertex_half_faces); }
    Span<std::uint32_t> face_half_faces() const { return view(chf_mesh_face_half_faces); }
    Span<std::uint32_t> boundary_half_faces() const {
        return view(chf_mesh_boundary_half_faces);
    }
    /// Boundary vertex -> volume vertex, and the component of each boundary vertex.
    Span<std::uint32_t> boundary_vertices() const { return view(chf_mesh_boundary_vertices); }
    Span<std::uint32_t> boundary_vertex_components() const {
        return view(chf_mesh_boundary_vertex_components);
    }
    Span<std::uint32_t> vertex_origins() const { return view(chf_mesh_vertex_origins); }
    Span<std::uint32_t> tetrahedron_origins() const {
        return view(chf_mesh_tetrahedron_origins);
    }
    /// x, y, z per vertex; empty without positions.
    Span<double> positions() const {
        std::size_t len = 0;
        const double *p = chf_mesh_positions(m_, &len);
        return Span<double>(p, p ? len : 0);
    }

    // Bulk relations.
    Csr vertex_vertices_csr() const { return csr(chf_mesh_vertex_vertices_csr); }
    Csr vertex_edges_csr() const { return csr(chf_mesh_vertex_edges_csr); }
    Csr vertex_faces_csr() const { return csr(chf_mesh_vertex_faces_csr); }
    Csr vertex_tetrahedra_csr() const { return csr(chf_mesh_vertex_tetrahedra_csr); }
    Csr edge_faces_csr() const { return csr(chf_mesh_edge_faces_csr); }
    Csr edge_tetrahedra_csr() const { return csr(chf_mesh_edge_tetrahedra_csr); }
    Csr tetrahedron_tetrahedra_csr() const { return csr(chf_mesh_tetrahedron_tetrahedra_csr); }

    // Summary, build report, memory.
    chf_summary summary() const {
        chf_summary s{};
        detail::check(chf_mesh_summary(m_, &s));
        return s;
    }
    chf_build_report report() const {
        chf_build_report r{};
        detail::check(chf_mesh_report(m_, &r));
        return r;
    }
    std::vector<std::uint32_t> report_examples(chf_report_kind kind) const {
        std::size_t len = 0;
        detail::check(chf_mesh_report_examples(m_, kind, nullptr, 0, &len));
        std::vector<std::uint32_t> out(len);
        detail::check(chf_mesh_report_examples(m_, kind, out.data(), out.size(), &len));
        return out;
    }
    chf_memory memory() const {
        chf_memory mem{};
        detail::check(chf_mesh_memory(m_, &mem));
        return mem;
    }

private:
    using RelationFn = topomesh_status (*)(const chf_mesh *, std::uint32_t, std::uint32_t *,
                                           std::size_t, std::size_t *);
    using ValueFn = topomesh_status (*)(const chf_mesh *, std::uint32_t, std::uint32_t *);
    using FlagFn = topomesh_status (*)(const chf_mesh *, std::uint32_t, bool *);
    using ViewFn = const std::uint32_t *(*)(const chf_mesh *, std::size_t *);
    using CsrFn = topomesh_status (*)(const chf_mesh *, std::uint32_t *, std::size_t,
                                      std::uint32_t *, std::size_t, std::size_t *,
                                      std::size_t *);

    /// One call into a stack buffer; a second into a vector of the needed size when longer.
    template <class T> IdList<T> list(RelationFn f, std::uint32_t id) const {
        std::array<std::uint32_t, 64> buf{};
        std::size_t len = 0;
        topomesh_status s = f(m_, id, buf.data(), buf.size(), &len);
        IdList<T> out;
        if (s == TOPOMESH_STATUS_BUFFER_TOO_SMALL) {
            std::vector<std::uint32_t> big(len);
            detail::check(f(m_, id, big.data(), big.size(), &len));
            out.reserve(len);
            for (std::size_t i = 0; i < len; i++) out.push_back(T{big[i]});
            return out;
        }
        detail::check(s);
        out.reserve(len);
        for (std::size_t i = 0; i < len; i++) out.push_back(T{buf[i]});
        return out;
    }
    template <class T, std::size_t N> std::array<T, N> fixed(RelationFn f, std::uint32_t id) const {
        std::array<std::uint32_t, N> ids{};
        std::size_t len = 0;
        detail::check(f(m_, id, ids.data(), N, &len));
        std::array<T, N> out{};
        for (std::size_t i = 0; i < N; i++) out[i] = T{ids[i]};
        return out;
    }
    template <class T, std::size_t N> SmallIds<T, N> small(RelationFn f, std::uint32_t id) const {
        std::array<std::uint32_t, N> ids{};
        std::size_t len = 0;
        detail::check(f(m_, id, ids.data(), N, &len));
        SmallIds<T, N> out;
        for (std::size_t i = 0; i < len; i++) out.push_back(T{ids[i]});
        return out;
    }
    std::uint32_t value(ValueFn f, std::uint32_t id) const {
        std::uint32_t out = none;
        detail::check(f(m_, id, &out));
        return out;
    }
    bool flag(FlagFn f, std::uint32_t id) const {
        bool out = false;
        detail::check(f(m_, id, &out));
        return out;
    }
    Span<std::uint32_t> view(ViewFn f) const {
        std::size_t len = 0;
        const std::uint32_t *p = f(m_, &len);
        return Span<std::uint32_t>(p, p ? len : 0);
    }
    Csr csr(CsrFn f) const {
        std::size_t n_offsets = 0, n_indices = 0;
        detail::check(f(m_, nullptr, 0, nullptr, 0, &n_offsets, &n_indices));
        Csr out;
        out.offsets.resize(n_offsets);
        out.indices.resize(n_indices);
        std::uint32_t dummy = 0;
        detail::check(f(m_, out.offsets.empty() ? &dummy : out.offsets.data(), n_offsets,
                        out.indices.empty() ? &dummy : out.indices.data(), n_indices,
                        &n_offsets, &n_indices));
        return out;
    }

    chf_mesh *m_ = nullptr;
};

/// The structure's name in the papers.
using Chf = Volume;

/// The library version ("0.1.0").
inline std::string version() { return topomesh_version(); }

} // namespace topomesh

#endif // TOPOMESH_HPP
