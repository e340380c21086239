// topomesh: header-only C++17 wrapper over the C API (topomesh.h).
//
//   topomesh::Surface s = topomesh::Surface::load("bunny.off");
//   for (topomesh::VertexId w : s.vertex_vertices(topomesh::VertexId{0})) { ... }
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
// - Relations are named as in the C API (vertex_vertices, edge_triangles, ...), the same on
//   Surface and Volume. Each per-element relation returns an Ids<T, N>: the ids by value,
//   up to N inline. A Surface keeps the zero-copy arrays of its level (V, O, VH, EH) and its
//   relations step inline over them where the level stores what they read, with the range
//   checks of the C API (a failing id goes through the C call, which reports it).
// - star(v) iterates the rotation around a surface vertex (StarStep: half-edge, vertex,
//   edge, triangle) without allocation.
// - Views are Span<T> (pointer + size) into the structure, valid until the mesh is
//   destroyed or its level changes. Bulk relations come as a Csr.
// - vertices(), edges(), triangles(), boundary_curves() (faces(), tetrahedra() on a Volume)
//   are ranges of strong ids (every id); live_vertices(), live_edges(), ... skip the ids
//   edits removed, as OpenMesh's and CGAL's element ranges do; position(v) is a Vec3;
//   VertexData<T>, EdgeData<T>, TriangleData<T>, FaceData<T>, TetData<T> hold the user's
//   data per element, indexed by the strong ids and sized from a mesh:
//   `VertexData<double> area(mesh, 0.0); area[v] = 1;`.
// - Thread safety is the C API's: const member functions may run concurrently;
//   build_level() and destruction need exclusive access.
//
// This file is the API, in a user's order; the implementation is in detail/.
#ifndef TOPOMESH_HPP
#define TOPOMESH_HPP

#include "topomesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace topomesh {

// ---------------------------------------------------------------------------------------
// Ids and element arithmetic
// ---------------------------------------------------------------------------------------

/// No element: boundary, none, invalid.
inline constexpr std::uint32_t none = TOPOMESH_NONE;

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
using FaceId = Id<struct FaceTag>;
using TetrahedronId = Id<struct TetrahedronTag>;
using HalfFaceId = Id<struct HalfFaceTag>;
/// A boundary curve of a surface (0 .. num_boundary_curves() - 1).
using CurveId = Id<struct CurveTag>;

/// Half-edge arithmetic (all levels): triangle t owns half-edges 3t, 3t+1, 3t+2.
constexpr TriangleId triangle_of(HalfEdgeId h) noexcept { return TriangleId{h.value() / 3u}; }
constexpr HalfEdgeId next(HalfEdgeId h) noexcept {
    return HalfEdgeId{h.value() % 3u == 2u ? h.value() - 2u : h.value() + 1u};
}
constexpr HalfEdgeId prev(HalfEdgeId h) noexcept {
    return HalfEdgeId{h.value() % 3u == 0u ? h.value() + 2u : h.value() - 1u};
}
constexpr HalfEdgeId first_half_edge(TriangleId t) noexcept { return HalfEdgeId{3u * t.value()}; }

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

/// Build options: the level (0..3) and strict mode (non-manifold input is an error).
struct Options {
    std::uint32_t level = 2;
    bool strict = false;
    /// Threads for the build (0: as many as the machine runs at once; the mesh is the same
    /// whatever the number).
    std::uint32_t threads = 0;
    /// A memory budget for the build in bytes (0: none): a build whose estimated peak
    /// exceeds it throws `Error` with `TOPOMESH_STATUS_OUT_OF_MEMORY` before allocating.
    std::uint64_t memory_limit_bytes = 0;
    /// Weld before building: vertices at most this distance apart (on the positions, which
    /// the weld needs) become one, the smallest id of each cluster of close vertices
    /// winning; the others keep their ids but lose their elements. 0 (the default) is off.
    double weld_tolerance = 0.0;
};

struct Csr;
struct SurfaceSummary;
struct SurfaceReport;
struct VolumeSummary;
struct VolumeReport;

} // namespace topomesh

// Span<T> (zero-copy arrays) and Ids<T, N> (per-element relations); StarRange (stars).
#include "detail/ranges.hpp"
#include "detail/calls.hpp"
#include "detail/star.hpp"
// Vec3 (positions), IdRange<I> (vertices(), edges(), ...), ElementData<I, T> (VertexData<T>,
// ...): the element ranges and the user's per-element data.
#include "detail/elements.hpp"
// HalfEdges, WingedEdges, CornerTable, CsrMatrix, SurfaceBetti, HalfFaces, ...: the exports.
#include "detail/export_types.hpp"

namespace topomesh {

// ---------------------------------------------------------------------------------------
// Surface: a triangle surface in the Compact Half-Edge structure (owns a che_mesh)
// ---------------------------------------------------------------------------------------

class Surface {
public:
    using Options = topomesh::Options;
    using Summary = SurfaceSummary;
    using BuildReport = SurfaceReport;

    // Create and free.
    /// From a flat triangle array (3 ids per triangle) over `n_vertices` vertices;
    /// `positions` is NULL or 3 doubles per vertex.
    static Surface from_triangles(const std::uint32_t *triangles, std::size_t n_triangles,
                                  std::size_t n_vertices, const double *positions = nullptr,
                                  Options options = {});
    /// From vectors: `triangles.size()` a multiple of 3; `positions` empty or 3 per vertex.
    static Surface from_triangles(const std::vector<std::uint32_t> &triangles,
                                  std::size_t n_vertices,
                                  const std::vector<double> &positions = {},
                                  Options options = {});
    /// Reads a surface file (.off .obj .ply .stl ...).
    static Surface load(const std::string &path, Options options = {});
    /// Opens a level file written by save() (no parsing, no build). `flags`: 0 checks
    /// everything, or TOPOMESH_OPEN_CHECKSUMS_ONLY / TOPOMESH_OPEN_TRUSTED; or'ed with
    /// TOPOMESH_OPEN_MAPPED, the file is mapped read-only and queried in place (zero-copy).
    /// Throws Error naming the section and byte of a damaged file.
    static Surface open(const std::string &path, std::uint32_t flags = 0);
    /// Takes ownership of a handle from the C API.
    explicit Surface(che_mesh *adopt) noexcept;
    Surface(const Surface &) = delete;
    Surface &operator=(const Surface &) = delete;
    Surface(Surface &&other) noexcept;
    Surface &operator=(Surface &&other) noexcept;
    ~Surface();
    const che_mesh *handle() const noexcept { return m_; }
    /// The handle, to pass to the C API. Change its level or edit it only through the
    /// Surface, or call refresh() after changing it through the handle: the Surface keeps
    /// the zero-copy arrays and the counts it last saw.
    che_mesh *handle() noexcept { return m_; }
    /// Gives up ownership; the caller frees with che_mesh_free.
    che_mesh *release() noexcept;
    /// Fetches the zero-copy arrays and counts again (after a change made through handle()).
    void refresh() noexcept { views_.fetch(m_); }

    // Level and counts.
    std::uint32_t level() const noexcept;
    /// Raises or lowers the level; invalidates views.
    void build_level(std::uint32_t level);
    std::size_t num_vertices() const noexcept;
    std::size_t num_input_vertices() const noexcept;
    std::size_t num_triangles() const noexcept;
    std::size_t num_edges() const noexcept;
    std::size_t num_half_edges() const noexcept;
    std::size_t num_boundary_curves() const noexcept;

    // Per-element relations. Around a vertex: counter-clockwise seen from outside, from
    // the boundary on a boundary vertex (the vertices and edges end with the closing one).
    Ids<VertexId> vertex_vertices(VertexId v) const;
    Ids<EdgeId> vertex_edges(VertexId v) const;
    Ids<TriangleId> vertex_triangles(VertexId v) const;
    Ids<VertexId, 2> edge_vertices(EdgeId e) const;
    Ids<EdgeId, 4> edge_edges(EdgeId e) const;
    Ids<TriangleId, 2> edge_triangles(EdgeId e) const;
    Ids<VertexId, 3> triangle_vertices(TriangleId t) const;
    Ids<EdgeId, 3> triangle_edges(TriangleId t) const;
    /// The triangle across each edge; invalid across a boundary edge.
    Ids<TriangleId, 3> triangle_triangles(TriangleId t) const;
    /// The vertices of boundary curve `curve`, in order.
    Ids<VertexId> boundary_curve_vertices(std::uint32_t curve) const;

    // Element ranges and positions. Every element of a kind, as strong ids in id order,
    // without storage, for loops and for sizing per-element data:
    //   for (VertexId v : s.vertices()) { Vec3 p = s.position(v); ... }
    //   VertexData<double> area(s, 0.0);  // one double per vertex: area[v]
    IdRange<VertexId> vertices() const noexcept { return IdRange<VertexId>(num_vertices()); }
    IdRange<TriangleId> triangles() const noexcept {
        return IdRange<TriangleId>(num_triangles());
    }
    IdRange<EdgeId> edges() const noexcept { return IdRange<EdgeId>(num_edges()); }
    IdRange<HalfEdgeId> half_edges() const noexcept {
        return IdRange<HalfEdgeId>(num_half_edges());
    }
    /// The ranges above hold every id, removed ones included; after edits these skip the
    /// removed ones (OpenMesh's and CGAL's vertices(), faces(), ...), until the mesh changes.
    LiveRange<VertexId, Surface> live_vertices() const noexcept {
        return {*this, num_vertices(), num_live_vertices()};
    }
    LiveRange<TriangleId, Surface> live_triangles() const noexcept {
        return {*this, num_triangles(), num_live_triangles()};
    }
    LiveRange<EdgeId, Surface> live_edges() const noexcept {
        return {*this, num_edges(), num_live_edges()};
    }
    /// The boundary curves (each a closed loop of boundary edges; see
    /// boundary_curve_vertices()).
    IdRange<CurveId> boundary_curves() const noexcept {
        return IdRange<CurveId>(num_boundary_curves());
    }
    Ids<VertexId> boundary_curve_vertices(CurveId curve) const;
    /// Whether the surface was built with positions.
    bool has_positions() const { return !positions().empty(); }
    /// The position of v; throws Error (OUT_OF_RANGE for a bad id, INVALID_INPUT when
    /// built without positions).
    Vec3 position(VertexId v) const;

    // Half-edges and boundary tests.
    HalfEdgeId opposite(HalfEdgeId h) const;
    EdgeId edge(HalfEdgeId h) const;
    /// The boundary curve of h, or `none`.
    std::uint32_t curve(HalfEdgeId h) const;
    HalfEdgeId half_edge(VertexId v) const;
    HalfEdgeId half_edge(EdgeId e) const;
    VertexId origin(HalfEdgeId h) const;
    VertexId target(HalfEdgeId h) const { return origin(next(h)); }
    bool is_boundary(VertexId v) const;
    bool is_boundary(EdgeId e) const;

    // Star iteration.
    /// The rotation around v, one StarStep per step, without allocation (inline from
    /// level 2). Throws Error from begin() when v is out of range.
    StarRange star(VertexId v) const noexcept { return StarRange(m_, v); }

    // Zero-copy views (empty below the level that stores them).
    Span<std::uint32_t> half_edge_vertices() const;
    Span<std::uint32_t> opposites() const;
    Span<std::uint32_t> vertex_half_edges() const;
    Span<std::uint32_t> edge_half_edges() const;
    Span<std::uint32_t> curve_half_edges() const;
    Span<std::uint32_t> vertex_origins() const;
    Span<std::uint32_t> triangle_origins() const;
    /// x, y, z per vertex; empty without positions.
    Span<double> positions() const;

    // Bulk relations.
    Csr vertex_vertices_csr() const;
    Csr vertex_edges_csr() const;
    Csr vertex_triangles_csr() const;
    Csr triangle_triangles_csr() const;

    // Exports: the classic representations (layouts in topomesh.h, che_mesh_export_*).
    HalfEdges halfedge(HalfEdgeOptions options = {}) const;
    WingedEdges winged() const;
    CornerTable corner() const;
    /// 2 per edge, in the direction of its canonical half-edge.
    std::vector<std::uint32_t> edge_list() const;
    /// 3 per triangle: the edge of each of its half-edges.
    std::vector<std::uint32_t> triangle_edges() const;
    CsrMatrix matrix(che_matrix_kind kind) const;
    SurfaceBetti betti() const;
    /// Triangle strips covering every triangle once in its orientation.
    std::vector<std::uint32_t> strips(StripList which = StripList::restarts) const;

    // Summary, build report, memory, validation.
    Summary summary() const;
    /// The C struct of summary().
    che_summary raw_summary() const;
    BuildReport report() const;
    /// The C struct of report().
    che_build_report raw_report() const;
    /// Ids of the elements a report count counts.
    std::vector<std::uint32_t> report_examples(che_report_kind kind) const;
    che_memory memory() const;
    /// Checks every invariant of the structure at its level; throws Error naming the first
    /// violation (element and rule). For tests and for data from untrusted code.
    void validate() const;

    // Editing in place (include/detail/edit.hpp). A refusal throws Error and changes
    // nothing; every edit invalidates the spans of the zero-copy views. Removed elements
    // keep their ids (num_* stay the id bounds, num_live_* count) until garbage_collect().
    VertexId add_vertex(const Vec3 *position = nullptr);
    TriangleId add_triangle(VertexId a, VertexId b, VertexId c);
    void remove(TriangleId t);
    /// Removes v and its star.
    void remove(VertexId v);
    void flip(EdgeId e);
    /// Splits edge e (or triangle t) at a new vertex, returned; position NULL: the
    /// midpoint (centroid) when the surface has positions.
    VertexId split(EdgeId e, const Vec3 *position = nullptr);
    VertexId split(TriangleId t, const Vec3 *position = nullptr);
    /// Merges the target of h into its origin (returned); refused by the link condition.
    VertexId collapse(HalfEdgeId h);
    /// Moves v (throws on a surface without positions).
    void set_position(VertexId v, Vec3 p);
    bool is_flip_ok(EdgeId e);
    bool is_collapse_ok(HalfEdgeId h);
    bool is_removed(VertexId v) const;
    bool is_removed(TriangleId t) const;
    bool is_removed(EdgeId e) const;
    std::size_t num_live_vertices() const noexcept;
    std::size_t num_live_triangles() const noexcept;
    std::size_t num_live_edges() const noexcept;
    /// Old id -> new id (`none` for a removed element).
    struct GarbageMaps {
        std::vector<std::uint32_t> vertices, triangles, edges;
    };
    /// Compacts the removed elements away; every id from before goes through the maps.
    GarbageMaps garbage_collect();

    // Writing.
    /// Writes the built surface to `path`, the format from its extension (.off .obj .ply
    /// .stl .vtk .mesh .msh): its oriented triangles, split copies as vertices of their own,
    /// and the input vertex of each where the format has an attribute. `flags`: 0 or an OR
    /// of TOPOMESH_WRITE_BINARY and TOPOMESH_WRITE_NO_ORIGIN. Whole or not at all; throws
    /// Error on failure.
    void write(const std::string &path, std::uint32_t flags = 0) const;
    /// Saves the built structure at its level as a level file (.che), whole or not at
    /// all; open() reads it back. Throws Error on failure.
    void save(const std::string &path) const;

    // Old names, kept for one release.
    [[deprecated("use vertex_vertices")]] Ids<VertexId> vertices_around(VertexId v) const {
        return vertex_vertices(v);
    }
    [[deprecated("use vertex_edges")]] Ids<EdgeId> edges_around(VertexId v) const {
        return vertex_edges(v);
    }
    [[deprecated("use vertex_triangles")]] Ids<TriangleId> triangles_around(VertexId v) const {
        return vertex_triangles(v);
    }

private:
    che_mesh *m_ = nullptr;
    detail::SurfaceViews views_;
    /// After an edit: the views fetched again, then `s` thrown if not OK.
    void edited(topomesh_status s);
};

// ---------------------------------------------------------------------------------------
// Volume: a tetrahedral mesh in the Compact Half-Face structure (owns a chf_mesh)
// ---------------------------------------------------------------------------------------

class Volume {
public:
    using Options = topomesh::Options;
    using Summary = VolumeSummary;
    using BuildReport = VolumeReport;

    // Create and free.
    /// From a flat tetrahedron array (4 ids per tetrahedron) over `n_vertices` vertices;
    /// `positions` is NULL or 3 doubles per vertex.
    static Volume from_tetrahedra(const std::uint32_t *tetrahedra, std::size_t n_tets,
                                  std::size_t n_vertices, const double *positions = nullptr,
                                  Options options = {});
    /// From vectors: `tetrahedra.size()` a multiple of 4; `positions` empty or 3 per vertex.
    static Volume from_tetrahedra(const std::vector<std::uint32_t> &tetrahedra,
                                  std::size_t n_vertices,
                                  const std::vector<double> &positions = {},
                                  Options options = {});
    /// Reads a volume file (.mesh .msh .vtk .node/.ele).
    static Volume load(const std::string &path, Options options = {});
    /// Opens a level file written by save(), as Surface::open does.
    static Volume open(const std::string &path, std::uint32_t flags = 0);
    /// Takes ownership of a handle from the C API.
    explicit Volume(chf_mesh *adopt) noexcept : m_(adopt) {}
    Volume(const Volume &) = delete;
    Volume &operator=(const Volume &) = delete;
    Volume(Volume &&other) noexcept;
    Volume &operator=(Volume &&other) noexcept;
    ~Volume();
    const chf_mesh *handle() const noexcept { return m_; }
    chf_mesh *handle() noexcept { return m_; }
    /// Gives up ownership; the caller frees with chf_mesh_free.
    chf_mesh *release() noexcept;

    // Level and counts.
    std::uint32_t level() const noexcept;
    /// Raises or lowers the level; invalidates views.
    void build_level(std::uint32_t level);
    std::size_t num_vertices() const noexcept;
    std::size_t num_input_vertices() const noexcept;
    std::size_t num_tetrahedra() const noexcept;
    std::size_t num_faces() const noexcept;
    std::size_t num_edges() const noexcept;
    std::size_t num_half_faces() const noexcept;
    /// Faces with exactly one tetrahedron.
    std::size_t num_boundary_faces() const noexcept;
    /// Unpaired half-faces (boundary faces, non-manifold and seam half-faces): the
    /// triangles of boundary().
    std::size_t num_boundary_triangles() const noexcept;
    std::size_t num_non_manifold_half_faces() const noexcept;
    std::size_t num_seam_half_faces() const noexcept;
    /// The vertices of boundary() (before its own split).
    std::size_t num_boundary_vertices() const noexcept;
    std::size_t num_boundary_components() const noexcept;

    // Per-element relations. Around a vertex: each once, in increasing order; around an
    // edge: rotation order, from the boundary on a boundary edge.
    Ids<VertexId> vertex_vertices(VertexId v) const;
    Ids<EdgeId> vertex_edges(VertexId v) const;
    Ids<FaceId> vertex_faces(VertexId v) const;
    Ids<TetrahedronId> vertex_tetrahedra(VertexId v) const;
    Ids<VertexId, 2> edge_vertices(EdgeId e) const;
    Ids<EdgeId> edge_edges(EdgeId e) const;
    Ids<FaceId> edge_faces(EdgeId e) const;
    Ids<TetrahedronId> edge_tetrahedra(EdgeId e) const;
    Ids<VertexId, 3> face_vertices(FaceId f) const;
    Ids<EdgeId, 3> face_edges(FaceId f) const;
    Ids<FaceId, 6> face_faces(FaceId f) const;
    Ids<TetrahedronId, 2> face_tetrahedra(FaceId f) const;
    Ids<VertexId, 4> tetrahedron_vertices(TetrahedronId t) const;
    Ids<EdgeId, 6> tetrahedron_edges(TetrahedronId t) const;
    Ids<FaceId, 4> tetrahedron_faces(TetrahedronId t) const;
    /// The tetrahedron across each face; invalid on the boundary.
    Ids<TetrahedronId, 4> tetrahedron_tetrahedra(TetrahedronId t) const;

    // Element ranges and positions, as on Surface:
    //   for (TetrahedronId t : vol.tetrahedra()) { ... }   TetData<double> volume(vol, 0.0);
    IdRange<VertexId> vertices() const noexcept { return IdRange<VertexId>(num_vertices()); }
    IdRange<EdgeId> edges() const noexcept { return IdRange<EdgeId>(num_edges()); }
    IdRange<FaceId> faces() const noexcept { return IdRange<FaceId>(num_faces()); }
    IdRange<TetrahedronId> tetrahedra() const noexcept {
        return IdRange<TetrahedronId>(num_tetrahedra());
    }
    IdRange<HalfFaceId> half_faces() const noexcept {
        return IdRange<HalfFaceId>(num_half_faces());
    }
    /// The ranges above hold every id, removed ones included; after edits these skip the
    /// removed ones (as CGAL's cell and vertex iterators do), until the volume changes.
    LiveRange<VertexId, Volume> live_vertices() const noexcept {
        return {*this, num_vertices(), num_live_vertices()};
    }
    LiveRange<EdgeId, Volume> live_edges() const noexcept {
        return {*this, num_edges(), num_live_edges()};
    }
    LiveRange<FaceId, Volume> live_faces() const noexcept {
        return {*this, num_faces(), num_live_faces()};
    }
    LiveRange<TetrahedronId, Volume> live_tetrahedra() const noexcept {
        return {*this, num_tetrahedra(), num_live_tetrahedra()};
    }
    /// Whether the volume was built with positions.
    bool has_positions() const { return !positions().empty(); }
    /// The position of v; throws Error (OUT_OF_RANGE for a bad id, INVALID_INPUT when
    /// built without positions).
    Vec3 position(VertexId v) const;

    // Half-faces and boundary tests.
    HalfFaceId opposite(HalfFaceId hf) const;
    FaceId face(HalfFaceId hf) const;
    HalfFaceId half_face(FaceId f) const;
    HalfFaceId half_face(VertexId v) const;
    bool is_boundary(VertexId v) const;
    bool is_boundary(EdgeId e) const;
    bool is_boundary(FaceId f) const;

    // The boundary surface and its maps.
    /// The boundary as a new Surface (level 3). Its vertices are the boundary vertices only,
    /// with compact ids: see boundary_vertex() and volume_vertex().
    Surface boundary() const;
    /// The boundary triangle of a half-face or face; invalid when interior.
    TriangleId boundary_triangle(HalfFaceId hf) const;
    TriangleId boundary_triangle(FaceId f) const;
    HalfFaceId boundary_half_face(TriangleId k) const;
    FaceId boundary_face(TriangleId k) const;
    /// The boundary component of v, or `none` off the boundary.
    std::uint32_t boundary_component(VertexId v) const;
    /// The vertex of boundary() that v is, or invalid off the boundary.
    VertexId boundary_vertex(VertexId v) const;
    /// The volume vertex of vertex b of boundary() (copies its split made included).
    VertexId volume_vertex(VertexId b) const;

    // Zero-copy views (empty below the level that stores them).
    Span<std::uint32_t> half_face_vertices() const;
    Span<std::uint32_t> opposites() const;
    Span<std::uint32_t> vertex_half_faces() const;
    Span<std::uint32_t> face_half_faces() const;
    Span<std::uint32_t> boundary_half_faces() const;
    /// Boundary vertex -> volume vertex, and the component of each boundary vertex.
    Span<std::uint32_t> boundary_vertices() const;
    Span<std::uint32_t> boundary_vertex_components() const;
    Span<std::uint32_t> vertex_origins() const;
    Span<std::uint32_t> tetrahedron_origins() const;
    /// x, y, z per vertex; empty without positions.
    Span<double> positions() const;

    // Bulk relations.
    Csr vertex_vertices_csr() const;
    Csr vertex_edges_csr() const;
    Csr vertex_faces_csr() const;
    Csr vertex_tetrahedra_csr() const;
    Csr edge_faces_csr() const;
    Csr edge_tetrahedra_csr() const;
    Csr tetrahedron_tetrahedra_csr() const;

    // Exports (layouts in topomesh.h, chf_mesh_export_*).
    HalfFaces halfface() const;
    /// 4 per tetrahedron: the tetrahedron across each face, `none` on the boundary.
    std::vector<std::uint32_t> dual_graph() const;
    CsrMatrix matrix(chf_matrix_kind kind) const;
    VolumeBetti betti() const;

    // Summary, build report, memory, validation.
    Summary summary() const;
    /// The C struct of summary().
    chf_summary raw_summary() const;
    BuildReport report() const;
    /// The C struct of report().
    chf_build_report raw_report() const;
    /// Ids of the elements a report count counts.
    std::vector<std::uint32_t> report_examples(chf_report_kind kind) const;
    chf_memory memory() const;
    /// Checks every invariant of the structure at its level; throws Error naming the first
    /// violation (element and rule). For tests and for data from untrusted code.
    void validate() const;

    // Writing.
    /// Writes the built volume to `path`, the format from its extension (.mesh .msh .vtk
    /// .node/.ele), as Surface::write does. Throws Error on failure.
    void write(const std::string &path, std::uint32_t flags = 0) const;
    /// Writes boundary() to `path` as a surface file, as Surface::write does; the origins
    /// are the input vertices of the volume. Throws Error on failure.
    void write_boundary(const std::string &path, std::uint32_t flags = 0) const;
    /// Saves the built structure at its level as a level file (.chf), whole or not at
    /// all; open() reads it back. Throws Error on failure.
    void save(const std::string &path) const;

    // Editing in place (include/detail/volume_edit.hpp). A refusal throws Error and
    // changes nothing; spans of the zero-copy views are invalid after an edit. Removed
    // elements keep their ids (num_* stay the id bounds, num_live_* count) until
    // garbage_collect(). Positions: nullptr for the default (the centroid of what is
    // split); a volume without positions takes nullptr only.
    VertexId add_vertex(const Vec3 *position = nullptr);
    /// Oriented by the determinant with positions, else by the faces it pairs with.
    TetrahedronId add_tetrahedron(VertexId a, VertexId b, VertexId c, VertexId d);
    void remove(TetrahedronId t);
    /// Removes v and its star.
    void remove(VertexId v);
    /// 1-4, 2-6 (1-3 on the boundary) and edge splits at a new vertex, returned. A 1-4
    /// split keeps `t` as the piece without its vertex 0 and appends the other three.
    VertexId split(TetrahedronId t, const Vec3 *position = nullptr);
    VertexId split(FaceId f, const Vec3 *position = nullptr);
    VertexId split(EdgeId e, const Vec3 *position = nullptr);
    /// The 2-3 flip of interior face f: the three new tetrahedra.
    std::array<TetrahedronId, 3> flip_23(FaceId f);
    /// The 3-2 flip of interior edge e (three tetrahedra around it): the two new ones.
    std::array<TetrahedronId, 2> flip_32(EdgeId e);
    /// Collapses half-edge `he` (3 * hf + j): its origin merges into its target (returned).
    VertexId collapse(std::uint64_t he);
    /// Would the operation succeed? Never throw for a refusal, never change anything.
    bool can_split(TetrahedronId t, const Vec3 *position = nullptr) const;
    bool can_flip_23(FaceId f) const;
    bool can_flip_32(EdgeId e) const;
    bool can_collapse(std::uint64_t he) const;
    /// The same questions as Surface::is_flip_ok: false for a refusal, Error for a bad or
    /// removed id.
    bool is_flip_23_ok(FaceId f) const;
    bool is_flip_32_ok(EdgeId e) const;
    bool is_collapse_ok(std::uint64_t he) const;
    bool is_removed(VertexId v) const;
    bool is_removed(TetrahedronId t) const;
    bool is_removed(FaceId f) const;
    bool is_removed(EdgeId e) const;
    std::size_t num_live_vertices() const noexcept;
    std::size_t num_live_tetrahedra() const noexcept;
    std::size_t num_live_faces() const noexcept;
    std::size_t num_live_edges() const noexcept;
    /// Old id -> new id (`none` for a removed element).
    struct GarbageMaps {
        std::vector<std::uint32_t> vertices, tetrahedra, faces, edges;
    };
    /// Compacts the removed elements away; every id from before goes through the maps.
    GarbageMaps garbage_collect();

private:
    chf_mesh *m_ = nullptr;
};

/// The structures' names in the papers.
using Che = Surface;
using Chf = Volume;

// ---------------------------------------------------------------------------------------
// Bulk relations
// ---------------------------------------------------------------------------------------

/// A bulk relation in compressed sparse rows: row i is indices[offsets[i] .. offsets[i+1]].
struct Csr {
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> indices;
    std::size_t rows() const noexcept { return offsets.empty() ? 0 : offsets.size() - 1; }
    Span<std::uint32_t> row(std::size_t i) const {
        return Span<std::uint32_t>(indices.data() + offsets.at(i), offsets.at(i + 1) - offsets[i]);
    }
};

// ---------------------------------------------------------------------------------------
// Summary and build report (the C structs with C++ types: raw_summary(), raw_report())
// ---------------------------------------------------------------------------------------

/// Surface::summary(): the counts and invariants of the surface (see che_summary).
struct SurfaceSummary {
    std::size_t vertices = 0, edges = 0, triangles = 0;
    std::size_t boundary_edges = 0;  ///< edges with exactly one triangle
    std::size_t boundary_curves = 0; ///< components of the boundary edges
    std::size_t components = 0;      ///< components of the triangles (through vertices)
    std::size_t isolated_vertices = 0;
    std::int64_t euler_characteristic = 0; ///< V - E + F of the input complex
    std::int64_t genus = 0; ///< sum of the component genera; -1 where undefined
    bool orientable = false, manifold = false;
    std::size_t dropped_degenerate = 0, non_manifold_edges = 0, split_vertices = 0;
    std::size_t flipped_triangles = 0, non_orientable_components = 0;
};

/// Surface::report(): what the build did to its input (see che_build_report).
struct SurfaceReport {
    std::size_t input_triangles = 0, input_vertices = 0, dropped_degenerate = 0;
    std::size_t duplicate_triangles = 0, input_edges = 0, boundary_edges = 0;
    std::size_t non_manifold_edges = 0, split_vertices = 0, seam_split_vertices = 0;
    std::size_t added_vertices = 0, flipped_triangles = 0, non_orientable_components = 0;
    std::size_t seam_edges = 0;
    std::size_t welded_vertices = 0; ///< merged into another by Options::weld_tolerance
};

/// Volume::summary(): the counts and invariants of the volume (see chf_summary).
struct VolumeSummary {
    std::size_t vertices = 0, edges = 0, faces = 0, tetrahedra = 0;
    std::size_t boundary_faces = 0, boundary_edges = 0, boundary_vertices = 0;
    std::size_t boundary_components = 0, components = 0, isolated_vertices = 0;
    std::int64_t euler_characteristic = 0;
    bool manifold = false, orientable = false;
    std::size_t dropped_degenerate = 0, zero_volume = 0, inverted_tetrahedra = 0;
    std::size_t non_manifold_faces = 0, non_manifold_edges = 0, split_vertices = 0;
    std::size_t flipped_tetrahedra = 0, non_orientable_components = 0;
};

/// Volume::report(): what the build did to its input (see chf_build_report).
struct VolumeReport {
    std::size_t input_tetrahedra = 0, input_vertices = 0, dropped_degenerate = 0;
    std::size_t zero_volume = 0, inverted_tetrahedra = 0, duplicate_tetrahedra = 0;
    std::size_t input_faces = 0, boundary_faces = 0, non_manifold_faces = 0;
    std::size_t input_edges = 0, non_manifold_edges = 0, kept_non_manifold_edges = 0;
    std::size_t split_vertices = 0, seam_split_vertices = 0, added_vertices = 0;
    std::size_t flipped_tetrahedra = 0, non_orientable_components = 0, seam_faces = 0;
    std::size_t welded_vertices = 0; ///< merged into another by Options::weld_tolerance
};

// ---------------------------------------------------------------------------------------
// Errors and version
// ---------------------------------------------------------------------------------------

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

/// The library version ("0.1.0").
inline std::string version() { return topomesh_version(); }

// ---------------------------------------------------------------------------------------
// The weld alone (what Options::weld_tolerance applies before a build)
// ---------------------------------------------------------------------------------------

/// For each vertex of `positions` (3 doubles per vertex), the smallest id of its cluster of
/// vertices at most `tolerance` apart (single linkage); itself when it welds to none.
/// Throws Error (INVALID_INPUT) for a tolerance that is not finite and positive.
inline std::vector<VertexId> weld_representatives(const std::vector<double> &positions,
                                                  double tolerance) {
    if (positions.size() % 3 != 0)
        throw Error(TOPOMESH_STATUS_INVALID_INPUT,
                    std::to_string(positions.size()) + " coordinates: not 3 per vertex");
    const std::size_t n = positions.size() / 3;
    std::vector<std::uint32_t> raw(n);
    std::size_t len = 0;
    const topomesh_status s = topomesh_weld_representatives(
        positions.data(), n, tolerance, raw.data(), raw.size(), &len);
    if (s != TOPOMESH_STATUS_OK) detail::throw_error(s);
    return std::vector<VertexId>(raw.begin(), raw.end());
}

// ---------------------------------------------------------------------------------------
// Old names, kept for one release
// ---------------------------------------------------------------------------------------

using Star = StarRange;
using VerticesAround [[deprecated("use Ids<VertexId>")]] = Ids<VertexId>;
using EdgesAround [[deprecated("use Ids<EdgeId>")]] = Ids<EdgeId>;
using TrianglesAround [[deprecated("use Ids<TriangleId>")]] = Ids<TriangleId>;
template <class T> using IdList [[deprecated("use Ids<T>")]] = Ids<T>;
template <class T, std::size_t N> using SmallIds [[deprecated("use Ids<T, N>")]] = Ids<T, N>;

} // namespace topomesh

#include "detail/error.hpp"
#include "detail/surface.hpp"
#include "detail/edit.hpp"
#include "detail/volume.hpp"
#include "detail/volume_edit.hpp"
#include "detail/element_members.hpp"
#include "detail/export.hpp"

#endif // TOPOMESH_HPP
