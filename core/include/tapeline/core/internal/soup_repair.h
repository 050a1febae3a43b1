// Validation and repair of a polygon soup before it becomes a mesh: checks that always reject,
// then (or, in strict mode, instead of) merging duplicate vertices, dropping unreferenced
// vertices, collapsed and repeated faces, and splitting non-manifold edges and vertices with
// CGAL::Polygon_mesh_processing::orient_polygon_soup (Guéziec et al., "Cutting and stitching",
// 2001). Every vertex keeps the index it had in the input, every face the input face it came from.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/coordinate_range.h>
#include <tapeline/core/internal/read_stl.h>  // ExactPointHash
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io_types.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

namespace tapeline::internal {

/// A soup ready to be turned into a mesh: only referenced, distinct points; every edge shared by
/// at most two faces with opposite orientations; every vertex a single fan.
struct PreparedSoup {
    std::vector<std::array<double, 3>> points;
    std::vector<std::size_t> point_origin;  // input vertex of each point
    std::vector<std::vector<std::size_t>> faces;
    std::vector<std::size_t> face_origin;  // input face of each face
    std::size_t input_vertex_count = 0;
    /// Per input vertex: the input vertex it was merged into (itself if it was not a duplicate).
    std::vector<std::size_t> representative;
};

/// Messages name elements by their input index, with the line when the format is text.
class SoupNames {
public:
    explicit SoupNames(const PolygonSoup& soup) : soup_(soup) {}
    std::string file() const { return soup_.file + ": "; }
    std::string vertex(std::size_t i) const {
        return (i < soup_.point_lines.size() ? at_line(soup_.point_lines[i]) : std::string()) +
               "vertex " + std::to_string(i);
    }
    std::string face(std::size_t f) const {
        return (f < soup_.face_lines.size() ? at_line(soup_.face_lines[f]) : std::string()) +
               "face " + std::to_string(f);
    }

private:
    const PolygonSoup& soup_;
};

inline std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// Checks that reject whatever the options: empty mesh, non-finite coordinates, faces with fewer
/// than 3 vertices, out-of-range indices, a vertex used twice by one face.
inline void validate_soup(const PolygonSoup& soup) {
    const SoupNames name(soup);
    if (soup.faces.empty()) {
        throw InvalidInput(name.file() + "empty mesh: no faces (" +
                           plural(soup.points.size(), "vertex", "vertices") + ")");
    }
    for (std::size_t i = 0; i < soup.points.size(); ++i) {
        const auto& p = soup.points[i];
        if (const char* bad = non_finite_kind(p[0], p[1], p[2]); *bad) {
            throw InvalidInput(name.file() + name.vertex(i) + " has " + bad);
        }
    }
    if (!soup.points.empty()) {
        check_coordinate_range(soup.file, soup.points.front().data(), soup.points.size(), 3,
                               "vertex");
    }
    const std::size_t n = soup.points.size();
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        const auto& face = soup.faces[f];
        if (face.size() < 3) {
            throw InvalidInput(name.file() + name.face(f) + " has only " +
                               std::to_string(face.size()) + " vertices (a face needs at least 3)");
        }
        for (std::size_t k = 0; k < face.size(); ++k) {
            if (face[k] >= n) {
                throw InvalidInput(name.file() + name.face(f) + " references vertex " +
                                   std::to_string(face[k]) + " but there are " + std::to_string(n) +
                                   " vertices");
            }
            for (std::size_t j = 0; j < k; ++j) {
                if (face[j] == face[k]) {
                    throw InvalidInput(name.file() + name.face(f) + " uses vertex " +
                                       std::to_string(face[k]) +
                                       " more than once (a face needs 3 distinct vertices)");
                }
            }
        }
    }
}

/// Disjoint sets with path halving, for fans around vertices.
class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), std::size_t{0});
    }
    std::size_t find(std::size_t x) {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];
            x = parent_[x];
        }
        return x;
    }
    void unite(std::size_t a, std::size_t b) {
        a = find(a);
        b = find(b);
        if (a != b) {
            parent_[std::max(a, b)] = std::min(a, b);
        }
    }

private:
    std::vector<std::size_t> parent_;
};

/// Records which point each split copy came from and which polygons were reversed.
struct OrientRecorder : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
    std::vector<std::size_t>* origin = nullptr;
    std::vector<char>* reversed = nullptr;
    void duplicated_vertex(std::size_t old_id, std::size_t new_id) {
        if (origin->size() <= new_id) {
            origin->resize(new_id + 1);
        }
        (*origin)[new_id] = (*origin)[old_id];
    }
    void polygon_orientation_reversed(std::size_t p) { (*reversed)[p] ^= 1; }
};

/// Validates, then repairs or (strict) rejects; fills the soup-level counts and warnings.
inline PreparedSoup prepare_soup(const PolygonSoup& soup, const MeshLoadOptions& options,
                                 MeshReport& report) {
    validate_soup(soup);
    const SoupNames name(soup);
    const std::size_t n = soup.points.size();
    auto warn = [&](const std::string& text) { report.warnings.push_back(name.file() + text); };
    auto reject = [&](const std::string& text) { throw TopologyError(name.file() + text); };

    // Polygons: triangulated later, on the mesh, where CGAL knows the polygon's plane.
    std::size_t first_polygon = soup.faces.size();
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        if (soup.faces[f].size() > 3) {
            if (first_polygon == soup.faces.size()) {
                first_polygon = f;
            }
            ++report.polygons_triangulated;
        }
    }
    if (report.polygons_triangulated > 0) {
        const std::string first = name.face(first_polygon) + " with " +
                                  std::to_string(soup.faces[first_polygon].size()) + " vertices";
        if (options.strict) {
            reject(first + "; strict mode accepts triangles only");
        }
        warn(plural(report.polygons_triangulated, "polygon face", "polygon faces") +
             " triangulated (first: " + first + ")");
    }

    // Unreferenced vertices map to no mesh vertex.
    std::vector<char> used(n, 0);
    for (const auto& face : soup.faces) {
        for (std::size_t v : face) {
            used[v] = 1;
        }
    }
    const auto first_unused = std::find(used.begin(), used.end(), 0);
    if (first_unused != used.end()) {
        const std::size_t i = static_cast<std::size_t>(first_unused - used.begin());
        report.unreferenced_vertices =
            static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
        if (options.strict) {
            reject(name.vertex(i) +
                   " is not used by any face; strict mode rejects unreferenced vertices");
        }
        warn(plural(report.unreferenced_vertices, "unreferenced vertex", "unreferenced vertices") +
             " dropped (first: " + name.vertex(i) + ")");
    }

    // Duplicate vertices: exactly equal coordinates, among referenced vertices.
    std::vector<std::size_t> rep(n);
    std::iota(rep.begin(), rep.end(), std::size_t{0});
    {
        std::unordered_map<std::array<double, 3>, std::size_t, ExactPointHash> seen;
        seen.reserve(n);
        std::size_t first_dup = n;
        for (std::size_t i = 0; i < n; ++i) {
            if (!used[i]) {
                continue;
            }
            const auto [it, inserted] = seen.emplace(soup.points[i], i);
            if (!inserted) {
                rep[i] = it->second;
                ++report.duplicate_vertices_merged;
                if (first_dup == n) {
                    first_dup = i;
                }
            }
        }
        if (report.duplicate_vertices_merged > 0) {
            const std::string first = name.vertex(first_dup) +
                                      " has the same coordinates as vertex " +
                                      std::to_string(rep[first_dup]);
            if (options.strict) {
                reject(first + "; strict mode rejects duplicate vertices");
            }
            warn(
                plural(report.duplicate_vertices_merged, "duplicate vertex", "duplicate vertices") +
                " merged (first: " + first + ")");
        }
    }

    // Faces after merging; collapsed ones (fewer than 3 distinct corners left) are dropped.
    std::vector<std::vector<std::size_t>> faces;
    std::vector<std::size_t> face_origin;
    faces.reserve(soup.faces.size());
    face_origin.reserve(soup.faces.size());
    std::size_t first_collapsed = soup.faces.size();
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        std::vector<std::size_t> face = soup.faces[f];
        bool collapsed = false;
        if (report.duplicate_vertices_merged > 0) {
            for (std::size_t& v : face) {
                v = rep[v];
            }
            for (std::size_t k = 0; k < face.size() && !collapsed; ++k) {
                for (std::size_t j = 0; j < k; ++j) {
                    if (face[j] == face[k]) {
                        collapsed = true;
                        break;
                    }
                }
            }
        }
        if (collapsed) {
            ++report.collapsed_faces_dropped;
            first_collapsed = std::min(first_collapsed, f);
            continue;
        }
        faces.push_back(std::move(face));
        face_origin.push_back(f);
    }
    if (report.collapsed_faces_dropped > 0) {
        warn(plural(report.collapsed_faces_dropped, "face", "faces") +
             " left with fewer than 3 distinct vertices by merging duplicates, dropped (first: " +
             name.face(first_collapsed) + ")");
    }

    // Repeated faces (same vertex set, either orientation): keep the first.
    {
        std::vector<std::pair<std::uint64_t, std::size_t>> keys(faces.size());
        std::vector<std::size_t> sorted;
        auto sorted_face = [&](std::size_t j) {
            sorted = faces[j];
            std::sort(sorted.begin(), sorted.end());
            return sorted;
        };
        for (std::size_t j = 0; j < faces.size(); ++j) {
            std::uint64_t h = faces[j].size();
            for (std::size_t v : sorted_face(j)) {
                h = (h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2))) * 0x100000001b3ULL;
            }
            keys[j] = {h, j};
        }
        std::sort(keys.begin(), keys.end());
        std::vector<char> drop(faces.size(), 0);
        std::size_t first_dup = faces.size(), first_dup_of = 0;
        for (std::size_t a = 0; a < keys.size();) {
            std::size_t b = a + 1;
            while (b < keys.size() && keys[b].first == keys[a].first) {
                ++b;
            }
            for (std::size_t x = a; x < b; ++x) {
                if (drop[keys[x].second]) {
                    continue;
                }
                const std::vector<std::size_t> sx = sorted_face(keys[x].second);
                for (std::size_t y = x + 1; y < b; ++y) {
                    if (!drop[keys[y].second] && sorted_face(keys[y].second) == sx) {
                        drop[keys[y].second] = 1;  // keys sorted by index within a hash
                        ++report.duplicate_faces_dropped;
                        if (face_origin[keys[y].second] < first_dup) {
                            first_dup = face_origin[keys[y].second];
                            first_dup_of = face_origin[keys[x].second];
                        }
                    }
                }
            }
            a = b;
        }
        if (report.duplicate_faces_dropped > 0) {
            const std::string first = name.face(first_dup) + " repeats face " +
                                      std::to_string(first_dup_of) + " (same vertices)";
            if (options.strict) {
                reject(first + "; strict mode rejects duplicate faces");
            }
            warn(plural(report.duplicate_faces_dropped, "duplicate face", "duplicate faces") +
                 " dropped (first: " + first + ")");
            std::size_t out = 0;
            for (std::size_t j = 0; j < faces.size(); ++j) {
                if (!drop[j]) {
                    if (out != j) {  // self-move would empty the face
                        faces[out] = std::move(faces[j]);
                        face_origin[out] = face_origin[j];
                    }
                    ++out;
                }
            }
            faces.resize(out);
            face_origin.resize(out);
        }
    }
    if (faces.empty()) {
        throw InvalidInput(name.file() + "empty mesh: no face is left after merging duplicates");
    }

    // Compact: referenced representatives, in input order.
    PreparedSoup out;
    out.input_vertex_count = n;
    out.representative = rep;
    {
        std::vector<std::size_t> index(n, n);
        for (const auto& face : faces) {
            for (std::size_t v : face) {
                index[v] = 0;
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (index[i] == 0) {
                index[i] = out.points.size();
                out.points.push_back(soup.points[i]);
                out.point_origin.push_back(i);
            }
        }
        for (auto& face : faces) {
            for (std::size_t& v : face) {
                v = index[v];
            }
        }
    }

    // Edges and fans. A half-edge record per face side, sorted by undirected edge.
    struct Side {
        std::size_t lo, hi, face;
        std::uint32_t pos;  // side from faces[face][pos] to faces[face][pos + 1]
        bool forward;       // lo -> hi
        bool operator<(const Side& o) const {
            return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : face < o.face;
        }
    };
    std::vector<std::size_t> corner_start(faces.size() + 1, 0);
    for (std::size_t j = 0; j < faces.size(); ++j) {
        corner_start[j + 1] = corner_start[j] + faces[j].size();
    }
    std::vector<Side> sides;
    sides.reserve(corner_start.back());
    for (std::size_t j = 0; j < faces.size(); ++j) {
        const auto& face = faces[j];
        for (std::size_t k = 0; k < face.size(); ++k) {
            const std::size_t a = face[k], b = face[(k + 1) % face.size()];
            sides.push_back(
                {std::min(a, b), std::max(a, b), j, static_cast<std::uint32_t>(k), a < b});
        }
    }
    std::sort(sides.begin(), sides.end());
    DisjointSets fans(corner_start.back());
    std::vector<char> on_nm_edge(out.points.size(), 0);
    std::size_t inconsistent = 0;
    std::string first_nm_edge;
    for (std::size_t a = 0; a < sides.size();) {
        std::size_t b = a + 1;
        while (b < sides.size() && sides[b].lo == sides[a].lo && sides[b].hi == sides[a].hi) {
            ++b;
        }
        const std::size_t count = b - a;
        if (count > 2) {
            if (report.non_manifold_edges++ == 0) {
                first_nm_edge = "edge between vertices " +
                                std::to_string(out.point_origin[sides[a].lo]) + " and " +
                                std::to_string(out.point_origin[sides[a].hi]) + ", shared by " +
                                std::to_string(count) + " faces:";
                for (std::size_t s = a; s < b && s < a + 6; ++s) {
                    first_nm_edge += " " + std::to_string(face_origin[sides[s].face]);
                }
                first_nm_edge += count > 6 ? " ..." : "";
            }
            on_nm_edge[sides[a].lo] = on_nm_edge[sides[a].hi] = 1;
        } else if (count == 2) {
            const Side& s = sides[a];
            const Side& t = sides[a + 1];
            inconsistent += s.forward == t.forward ? 1 : 0;
            auto corner = [&](const Side& side, bool at_lo) {
                const std::size_t size = faces[side.face].size();
                const bool source = side.forward == at_lo;  // lo is the side's source
                return corner_start[side.face] + (source ? side.pos : (side.pos + 1) % size);
            };
            fans.unite(corner(s, true), corner(t, true));
            fans.unite(corner(s, false), corner(t, false));
        }
        a = b;
    }
    std::vector<std::uint32_t> fan_count(out.points.size(), 0);
    for (std::size_t j = 0; j < faces.size(); ++j) {
        for (std::size_t k = 0; k < faces[j].size(); ++k) {
            const std::size_t c = corner_start[j] + k;
            if (fans.find(c) == c) {
                ++fan_count[faces[j][k]];
            }
        }
    }
    std::size_t first_nm_vertex = out.points.size();
    for (std::size_t v = 0; v < out.points.size(); ++v) {
        if (fan_count[v] > 1 && !on_nm_edge[v]) {
            if (report.non_manifold_vertices++ == 0) {
                first_nm_vertex = v;
            }
        }
    }
    if (report.non_manifold_edges > 0) {
        if (options.strict) {
            reject(first_nm_edge + "; strict mode rejects non-manifold edges");
        }
        warn(plural(report.non_manifold_edges, "non-manifold edge", "non-manifold edges") +
             " split (first: " + first_nm_edge + ")");
    }
    if (report.non_manifold_vertices > 0) {
        const std::string first = name.vertex(out.point_origin[first_nm_vertex]) + ", where " +
                                  std::to_string(fan_count[first_nm_vertex]) +
                                  " separate fans of faces meet";
        if (options.strict) {
            reject(first + "; strict mode rejects non-manifold vertices");
        }
        warn(plural(report.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") +
             " split (first: " + first + ")");
    }

    // Orientation and splitting, only when needed: the CGAL orienter is map-based and slow on
    // meshes that are fine already.
    if (report.non_manifold_edges > 0 || report.non_manifold_vertices > 0 || inconsistent > 0) {
        std::vector<char> reversed(faces.size(), 0);
        OrientRecorder recorder;
        recorder.origin = &out.point_origin;
        recorder.reversed = &reversed;
        const std::size_t before = out.points.size();
        CGAL::Polygon_mesh_processing::orient_polygon_soup(out.points, faces,
                                                           CGAL::parameters::visitor(recorder));
        report.vertices_split = out.points.size() - before;
        out.point_origin.resize(out.points.size());
        if (report.vertices_split > 0) {
            const std::string first = "vertex " + std::to_string(out.point_origin[before]);
            if (options.strict) {
                reject("the faces cannot be oriented consistently without splitting " + first +
                       " (non-orientable surface); strict mode rejects this");
            }
            warn(plural(report.vertices_split, "vertex copy", "vertex copies") +
                 " added to make the mesh manifold and orientable (first: a copy of " + first +
                 ")");
        }
        std::size_t first_reversed = soup.faces.size();
        for (std::size_t j = 0; j < faces.size(); ++j) {
            if (reversed[j]) {
                ++report.faces_reoriented;
                first_reversed = std::min(first_reversed, face_origin[j]);
            }
        }
        if (report.faces_reoriented > 0) {
            warn(plural(report.faces_reoriented, "face", "faces") +
                 " reversed to agree with their neighbours' orientation (first: " +
                 name.face(first_reversed) + ")");
        }
    }
    out.faces = std::move(faces);
    out.face_origin = std::move(face_origin);
    return out;
}

}  // namespace tapeline::internal
