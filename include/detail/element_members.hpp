// topomesh C++ wrapper, implementation: the members of Surface and Volume declared in
// topomesh.hpp's "Element ranges and positions" blocks (the types are in
// detail/elements.hpp).
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_ELEMENT_MEMBERS_HPP
#define TOPOMESH_DETAIL_ELEMENT_MEMBERS_HPP

namespace topomesh {

// The members of Surface and Volume declared in topomesh.hpp's "Element ranges" blocks.

inline Vec3 Surface::position(VertexId v) const {
    if (views_.P != nullptr && views_.vertex(v.value())) {
        const double *q = views_.P + 3 * static_cast<std::size_t>(v.value());
        return Vec3{q[0], q[1], q[2]};
    }
    return detail::position_at(positions(), num_vertices(), v);
}
inline Ids<VertexId> Surface::boundary_curve_vertices(CurveId c) const {
    return boundary_curve_vertices(c.value());
}
inline Vec3 Volume::position(VertexId v) const {
    return detail::position_at(positions(), num_vertices(), v);
}

} // namespace topomesh

#endif // TOPOMESH_DETAIL_ELEMENT_MEMBERS_HPP
