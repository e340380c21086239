// topomesh C++ wrapper, implementation: what users of OpenMesh and geometry-central expect
// beside the relations.
//
//   Vec3              a position: x, y, z, and operator[].
//   IdRange<Id>       the ids 0 .. n-1 of one kind of element as strong ids, without
//                     storage: Surface::vertices(), triangles(), edges(), boundary_curves(),
//                     and Volume::vertices(), edges(), faces(), tetrahedra().
//   LiveRange<Id, M>  the ids of one kind not removed by edits, skipping the removed ones:
//                     Surface::live_vertices(), ..., Volume::live_tetrahedra(), ...
//   ElementData<Id,T> a dense vector of the user's data indexed by a strong id and sized
//                     from a mesh: VertexData<T>, EdgeData<T>, TriangleData<T>, ...
//
// The members of Surface and Volume that use them are in detail/element_members.hpp.
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_ELEMENTS_HPP
#define TOPOMESH_DETAIL_ELEMENTS_HPP

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace topomesh {

/// A position (or any 3-vector): x, y, z, also as [0], [1], [2].
struct Vec3 {
    double x = 0.0, y = 0.0, z = 0.0;
    double &operator[](std::size_t i) noexcept { return i == 0 ? x : i == 1 ? y : z; }
    const double &operator[](std::size_t i) const noexcept { return i == 0 ? x : i == 1 ? y : z; }
    friend bool operator==(const Vec3 &a, const Vec3 &b) noexcept {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    }
    friend bool operator!=(const Vec3 &a, const Vec3 &b) noexcept { return !(a == b); }
};

/// The ids 0 .. size()-1 of one kind of element, as the strong id type I; nothing stored.
/// The count is taken when the range is made: a range of a mesh stays valid as long as
/// the mesh is not rebuilt (a level change keeps every id).
template <class I> class IdRange {
public:
    class iterator {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = I;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = I;
        constexpr iterator() noexcept = default;
        constexpr explicit iterator(std::uint32_t i) noexcept : i_(i) {}
        constexpr I operator*() const noexcept { return I{i_}; }
        constexpr I operator[](difference_type n) const noexcept {
            return I{static_cast<std::uint32_t>(i_ + n)};
        }
        constexpr iterator &operator++() noexcept { ++i_; return *this; }
        constexpr iterator operator++(int) noexcept { return iterator(i_++); }
        constexpr iterator &operator--() noexcept { --i_; return *this; }
        constexpr iterator operator--(int) noexcept { return iterator(i_--); }
        constexpr iterator &operator+=(difference_type n) noexcept {
            i_ = static_cast<std::uint32_t>(i_ + n);
            return *this;
        }
        constexpr iterator &operator-=(difference_type n) noexcept { return *this += -n; }
        friend constexpr iterator operator+(iterator it, difference_type n) noexcept {
            return it += n;
        }
        friend constexpr iterator operator+(difference_type n, iterator it) noexcept {
            return it += n;
        }
        friend constexpr iterator operator-(iterator it, difference_type n) noexcept {
            return it -= n;
        }
        friend constexpr difference_type operator-(iterator a, iterator b) noexcept {
            return static_cast<difference_type>(a.i_) - static_cast<difference_type>(b.i_);
        }
        friend constexpr bool operator==(iterator a, iterator b) noexcept { return a.i_ == b.i_; }
        friend constexpr bool operator!=(iterator a, iterator b) noexcept { return a.i_ != b.i_; }
        friend constexpr bool operator<(iterator a, iterator b) noexcept { return a.i_ < b.i_; }
        friend constexpr bool operator>(iterator a, iterator b) noexcept { return a.i_ > b.i_; }
        friend constexpr bool operator<=(iterator a, iterator b) noexcept { return a.i_ <= b.i_; }
        friend constexpr bool operator>=(iterator a, iterator b) noexcept { return a.i_ >= b.i_; }

    private:
        std::uint32_t i_ = 0;
    };
    using value_type = I;
    using const_iterator = iterator;

    constexpr IdRange() noexcept = default;
    constexpr explicit IdRange(std::size_t n) noexcept : n_(static_cast<std::uint32_t>(n)) {}
    constexpr iterator begin() const noexcept { return iterator(0); }
    constexpr iterator end() const noexcept { return iterator(n_); }
    constexpr std::size_t size() const noexcept { return n_; }
    constexpr bool empty() const noexcept { return n_ == 0; }
    constexpr I operator[](std::size_t i) const noexcept { return I{static_cast<std::uint32_t>(i)}; }

private:
    std::uint32_t n_ = 0;
};

/// The ids of one kind of element that are not removed, in increasing order, as the strong
/// id type I: what OpenMesh's and CGAL's vertices(), faces(), ... iterate after deletions.
/// A forward range over a mesh (Surface or Volume) that asks the mesh's is_removed(I) of
/// each id, and nothing at all when the mesh has no removed element of the kind. It
/// borrows the mesh: valid until the mesh is edited, collected or destroyed.
template <class I, class Mesh> class LiveRange {
public:
    /// Holds what it needs by value (the mesh pointer, the bound): an iterator outlives
    /// the range it came from.
    class iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = I;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = I;
        iterator() noexcept = default;
        iterator(const Mesh *mesh, std::uint32_t i, std::uint32_t n, bool holes)
            : mesh_(mesh), i_(i), n_(n), holes_(holes) {
            skip();
        }
        I operator*() const noexcept { return I{i_}; }
        iterator &operator++() {
            ++i_;
            skip();
            return *this;
        }
        iterator operator++(int) {
            iterator it = *this;
            ++*this;
            return it;
        }
        friend bool operator==(const iterator &a, const iterator &b) noexcept {
            return a.i_ == b.i_;
        }
        friend bool operator!=(const iterator &a, const iterator &b) noexcept {
            return a.i_ != b.i_;
        }

    private:
        // Past removed ids, when the mesh has any.
        void skip() {
            if (holes_)
                while (i_ < n_ && mesh_->is_removed(I{i_})) ++i_;
        }
        const Mesh *mesh_ = nullptr;
        std::uint32_t i_ = 0, n_ = 0;
        bool holes_ = false;
    };
    using value_type = I;
    using const_iterator = iterator;

    /// The ids below `n` of `mesh` not removed, `live` of them.
    LiveRange(const Mesh &mesh, std::size_t n, std::size_t live) noexcept
        : mesh_(&mesh), n_(static_cast<std::uint32_t>(n)), live_(live) {}
    iterator begin() const { return iterator(mesh_, 0, n_, live_ != n_); }
    iterator end() const noexcept { return iterator(mesh_, n_, n_, false); }
    /// The live count (the mesh's num_live_*).
    std::size_t size() const noexcept { return live_; }
    bool empty() const noexcept { return live_ == 0; }

private:
    const Mesh *mesh_;
    std::uint32_t n_;
    std::size_t live_;
};

namespace detail {

/// How many elements of the kind I a mesh has: the size ElementData<I, T> takes from it.
template <class I> struct ElementCount;
template <> struct ElementCount<VertexId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_vertices(); }
};
template <> struct ElementCount<EdgeId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_edges(); }
};
template <> struct ElementCount<TriangleId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_triangles(); }
};
template <> struct ElementCount<HalfEdgeId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_half_edges(); }
};
template <> struct ElementCount<CurveId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_boundary_curves(); }
};
template <> struct ElementCount<FaceId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_faces(); }
};
template <> struct ElementCount<TetrahedronId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_tetrahedra(); }
};
template <> struct ElementCount<HalfFaceId> {
    template <class Mesh> static std::size_t of(const Mesh &m) { return m.num_half_faces(); }
};

/// Vertex v's position out of a positions span (3 doubles per vertex), or Error.
inline Vec3 position_at(Span<double> p, std::size_t n_vertices, VertexId v) {
    if (p.empty())
        throw_error(TOPOMESH_STATUS_INVALID_INPUT, "the mesh was built without positions");
    if (v.value() >= n_vertices)
        throw_error(TOPOMESH_STATUS_OUT_OF_RANGE,
                    "vertex " + std::to_string(v.value()) + " (there are " +
                        std::to_string(n_vertices) + " vertices)");
    const double *q = p.data() + 3 * static_cast<std::size_t>(v.value());
    return Vec3{q[0], q[1], q[2]};
}

} // namespace detail

/// The user's data per element: a dense std::vector<T> indexed by the strong id I, sized
/// from a mesh (as geometry-central's MeshData). `operator[]` does not check the id,
/// `at()` does. It holds no reference to the mesh: size it again after building another.
template <class I, class T> class ElementData {
public:
    using value_type = T;
    using reference = typename std::vector<T>::reference;
    using const_reference = typename std::vector<T>::const_reference;
    using iterator = typename std::vector<T>::iterator;
    using const_iterator = typename std::vector<T>::const_iterator;

    ElementData() = default;
    /// One `init` per element of the kind I in `mesh` (a Surface or a Volume).
    template <class Mesh>
    explicit ElementData(const Mesh &mesh, const T &init = T())
        : data_(detail::ElementCount<I>::of(mesh), init) {}
    /// `n` elements, each `init`.
    explicit ElementData(std::size_t n, const T &init = T()) : data_(n, init) {}

    reference operator[](I id) { return data_[id.value()]; }
    const_reference operator[](I id) const { return data_[id.value()]; }
    reference at(I id) { return data_.at(checked(id)); }
    const_reference at(I id) const { return data_.at(checked(id)); }

    std::size_t size() const noexcept { return data_.size(); }
    bool empty() const noexcept { return data_.empty(); }
    void fill(const T &value) { data_.assign(data_.size(), value); }
    iterator begin() noexcept { return data_.begin(); }
    iterator end() noexcept { return data_.end(); }
    const_iterator begin() const noexcept { return data_.begin(); }
    const_iterator end() const noexcept { return data_.end(); }
    /// The values in id order, to hand to other code.
    std::vector<T> &raw() noexcept { return data_; }
    const std::vector<T> &raw() const noexcept { return data_; }

private:
    std::size_t checked(I id) const {
        if (id.value() >= data_.size())
            throw std::out_of_range("topomesh::ElementData::at: id " +
                                    std::to_string(id.value()) + " of " +
                                    std::to_string(data_.size()));
        return id.value();
    }

    std::vector<T> data_;
};

template <class T> using VertexData = ElementData<VertexId, T>;
template <class T> using EdgeData = ElementData<EdgeId, T>;
template <class T> using TriangleData = ElementData<TriangleId, T>;
template <class T> using HalfEdgeData = ElementData<HalfEdgeId, T>;
template <class T> using CurveData = ElementData<CurveId, T>;
template <class T> using FaceData = ElementData<FaceId, T>;
template <class T> using TetrahedronData = ElementData<TetrahedronId, T>;
template <class T> using TetData = TetrahedronData<T>;
template <class T> using HalfFaceData = ElementData<HalfFaceId, T>;

} // namespace topomesh

#endif // TOPOMESH_DETAIL_ELEMENTS_HPP
