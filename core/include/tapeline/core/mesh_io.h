// Reading triangle meshes from OFF, OBJ, PLY and STL with precise rejections and reported repairs.
//
// Small format readers produce a polygon soup and say which line or element is broken (CGAL's
// readers only return a bool). The soup-to-mesh work uses CGAL Polygon Mesh Processing:
// orient_polygon_soup splits non-manifold vertices and edges (Guéziec, Taubin, Lazarus, Horn,
// "Cutting and stitching: converting sets of polygons to manifold surfaces", IEEE TVCG 2001),
// triangulate_faces cuts polygons, connected_components and extract_boundary_cycles measure the
// result. Every mesh vertex remembers the input vertex it came from, because users address
// vertices by their index in the file. See core/README.md for every check and what happens.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/build_mesh.h>
#include <tapeline/core/internal/read_obj.h>
#include <tapeline/core/internal/read_off.h>
#include <tapeline/core/internal/read_ply.h>
#include <tapeline/core/internal/read_stl.h>
#include <tapeline/core/internal/soup_repair.h>
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io_types.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tapeline {

/// Reads a mesh file into a polygon soup with the file's own numbering; the format comes from the
/// extension (.off, .obj, .ply, .stl, any case). Rejects (InvalidInput, naming the file and the
/// line or element) missing, empty, truncated or unparsable files, NaN/Inf coordinates, faces
/// with fewer than 3 vertices and out-of-range indices.
///
/// \throws InvalidInput on an unknown extension, a file that cannot be read, or any of the
///         rejections above.
inline PolygonSoup read_polygon_soup(const std::string& path) {
    const std::string ext = internal::lower_extension(path);
    if (ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl") {
        throw InvalidInput(path + ": unknown mesh format '" + ext +
                           "' (expected .off, .obj, .ply or .stl)");
    }
    const std::string bytes = internal::load_file(path);
    if (ext == ".off") {
        return internal::read_off(path, bytes);
    }
    if (ext == ".obj") {
        return internal::read_obj(path, bytes);
    }
    if (ext == ".ply") {
        return internal::read_ply(path, bytes);
    }
    return internal::read_stl(path, bytes);
}

namespace internal {

inline void check_options(const std::string& name, const MeshLoadOptions& options) {
    if (!(options.needle_angle_degrees >= 0.0 && options.needle_angle_degrees <= 60.0)) {
        throw InvalidInput(name + ": needle_angle_degrees must be between 0 and 60, got " +
                           std::to_string(options.needle_angle_degrees));
    }
}

template <class TriangleMesh>
void load_soup_into(const PolygonSoup& soup, const MeshLoadOptions& options,
                    LoadedMesh<TriangleMesh>& result) {
    result.report.file = soup.file;
    result.report.format = soup.format;
    result.report.input_vertices = soup.points.size();
    result.report.input_faces = soup.faces.size();
    result.input_vertex_count = soup.points.size();
    PreparedSoup prepared = prepare_soup(soup, options, result.report);
    build_loaded_mesh(std::move(prepared), soup, options, result);
}

}  // namespace internal

/// Reads a triangle mesh (CGAL MutableFaceGraph, e.g. CGAL::Surface_mesh) from OFF, OBJ, PLY or
/// STL; validates, repairs (or, strict, rejects) and reports as described in core/README.md.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` with an internal
///         vertex point map (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), default
///         constructible.
/// \param path the file; the format comes from its extension.
/// \param options strict mode and the needle-angle threshold.
/// \throws InvalidInput on an unknown extension, an unreadable, empty, truncated or unparsable
///         file, naming the file and the line or element.
/// \throws InvalidInput naming the file and the element: no faces, a NaN or infinite
///         coordinate, a face with fewer than 3 vertices or an out-of-range index, a
///         `needle_angle_degrees` outside [0, 60].
/// \throws TopologyError in strict mode on polygons, duplicate vertices or faces,
///         non-manifold edges or vertices, or faces that cannot be oriented consistently.
template <class TriangleMesh>
LoadedMesh<TriangleMesh> read_triangle_mesh(const std::string& path,
                                            const MeshLoadOptions& options = {}) {
    internal::check_options(path, options);
    LoadedMesh<TriangleMesh> result;  // filled in place: Polyhedron handles do not survive a copy
    const PolygonSoup soup = read_polygon_soup(path);
    internal::load_soup_into(soup, options, result);
    return result;
}

/// Same validation and repair on an in-memory polygon soup (`name` is used in messages).
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` with an internal
///         vertex point map (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), default
///         constructible.
/// \throws InvalidInput naming the file and the element: no faces, a NaN or infinite
///         coordinate, a face with fewer than 3 vertices or an out-of-range index, a
///         `needle_angle_degrees` outside [0, 60].
/// \throws TopologyError in strict mode on polygons, duplicate vertices or faces,
///         non-manifold edges or vertices, or faces that cannot be oriented consistently.
template <class TriangleMesh>
LoadedMesh<TriangleMesh> triangle_mesh_from_soup(const std::vector<std::array<double, 3>>& points,
                                                 const std::vector<std::vector<std::size_t>>& faces,
                                                 const std::string& name,
                                                 const MeshLoadOptions& options = {}) {
    internal::check_options(name, options);
    LoadedMesh<TriangleMesh> result;
    PolygonSoup soup;
    soup.file = name;
    soup.format = "soup";
    soup.points = points;
    soup.faces = faces;
    internal::load_soup_into(soup, options, result);
    return result;
}

}  // namespace tapeline
