// Reading point sets (no faces) from .xyz, .csv and .ply, with rejections that name the file and
// the line. No CGAL.
//
//   .xyz   one point per line, its coordinates separated by blanks; any number D >= 2 of them,
//          the same on every line; `#` comments and blank lines are skipped.
//   .csv   one point per line, coordinates separated by commas; an optional first line of
//          column names (any non-numeric field in the first non-blank line makes it a header).
//   .ply   the `vertex` element's x, y, z (tapeline's PLY reader: ascii and binary); faces, if
//          any, are ignored; nx, ny, nz vertex properties become the normals.
//
// CGAL's read_points (Point_set_processing_3) reads .xyz and .ply too, but only into 3D points
// with a kernel, and reports a bad line as a bare `false`; the messages here say where.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/coordinate_range.h>
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace tapeline {

/// n points of dimension `dimension`, point i at [dimension i, dimension i + dimension).
struct PointSet {
    /// Source file, and format: "xyz", "csv" or "ply".
    ///@{
    std::string file, format;  ///< format: "xyz", "csv" or "ply"
    ///@}
    std::size_t dimension = 0;        ///< coordinates per point
    std::vector<double> coordinates;  ///< `dimension` per point, in file order
    std::vector<double> normals;      ///< 3 per point when the PLY has nx, ny, nz; else empty
    /// number of points
    std::size_t size() const { return dimension ? coordinates.size() / dimension : 0; }
};

namespace internal {

inline PointSet read_delimited_points(const std::string& path, std::string_view text, bool csv) {
    PointSet out;
    out.file = path;
    out.format = csv ? "csv" : "xyz";
    LineScanner lines(text);
    std::string_view line;
    std::uint32_t first_data_line = 0;
    bool first = true;
    std::vector<std::string_view> fields;
    while (lines.next(line)) {
        if (!csv)
            line = strip_comment(line);
        if (is_blank(line))
            continue;
        const std::uint32_t ln = lines.line_number();
        fields.clear();
        if (csv) {
            std::size_t start = 0;
            for (;;) {
                const std::size_t comma = line.find(',', start);
                std::string_view f =
                    line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                       : comma - start);
                while (!f.empty() && is_space(f.front()))
                    f.remove_prefix(1);
                while (!f.empty() && is_space(f.back()))
                    f.remove_suffix(1);
                fields.push_back(f);
                if (comma == std::string_view::npos)
                    break;
                start = comma + 1;
            }
        } else {
            Tokens tokens(line);
            std::string_view t;
            while (tokens.next(t))
                fields.push_back(t);
        }
        const bool header_line = first && csv;
        first = false;
        double v = 0;
        if (header_line) {
            bool numeric = true;
            for (auto f : fields)
                numeric = numeric && parse_double(f, v);
            if (!numeric)
                continue;  // column names
        }
        if (out.dimension == 0) {
            if (fields.size() < 2)
                throw InvalidInput(path + ": " + at_line(ln) + "a point needs at least 2 " +
                                   "coordinates, found " + std::to_string(fields.size()));
            out.dimension = fields.size();
            first_data_line = ln;
        } else if (fields.size() != out.dimension) {
            throw InvalidInput(path + ": " + at_line(ln) + std::to_string(fields.size()) +
                               " coordinates, but line " + std::to_string(first_data_line) +
                               " has " + std::to_string(out.dimension));
        }
        for (std::size_t j = 0; j < fields.size(); ++j) {
            if (!parse_double(fields[j], v))
                throw InvalidInput(path + ": " + at_line(ln) + "coordinate " +
                                   std::to_string(j + 1) + " " + quoted(fields[j]) +
                                   " is not a number");
            if (!std::isfinite(v))
                throw InvalidInput(path + ": " + at_line(ln) + "coordinate " +
                                   std::to_string(j + 1) + " is " +
                                   (std::isnan(v) ? "NaN" : "infinite"));
            out.coordinates.push_back(v);
        }
    }
    if (out.coordinates.empty())
        throw InvalidInput(path + ": no points");
    return out;
}

}  // namespace internal

/// Reads a point set; the format follows the extension (.xyz, .csv, .ply, any case). InvalidInput
/// naming the file (and line) for a missing file, an unknown extension, a malformed line, a
/// non-finite coordinate, rows of different lengths or no points.
///
/// \throws InvalidInput naming the file (and line) on any of the rejections above.
inline PointSet read_point_set(const std::string& path) {
    const std::string ext = internal::lower_extension(path);
    if (ext != ".xyz" && ext != ".csv" && ext != ".ply")
        throw InvalidInput(path + ": unknown point-set format '" + ext +
                           "' (expected .xyz, .csv or .ply)");
    if (ext == ".ply") {
        const PolygonSoup soup = read_polygon_soup(path);
        PointSet out;
        out.file = path;
        out.format = "ply";
        out.dimension = 3;
        for (std::size_t i = 0; i < soup.points.size(); ++i) {
            const auto& p = soup.points[i];
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                throw InvalidInput(path + ": vertex " + std::to_string(i) +
                                   " has a non-finite coordinate");
            out.coordinates.insert(out.coordinates.end(), p.begin(), p.end());
        }
        const auto nx = soup.vertex_properties.find("nx"), ny = soup.vertex_properties.find("ny"),
                   nz = soup.vertex_properties.find("nz");
        const auto end = soup.vertex_properties.end();
        if (nx != end && ny != end && nz != end)
            for (std::size_t i = 0; i < soup.points.size(); ++i)
                out.normals.insert(out.normals.end(),
                                   {nx->second[i], ny->second[i], nz->second[i]});
        if (out.coordinates.empty())
            throw InvalidInput(path + ": no points");
        internal::check_coordinate_range(path, out.coordinates.data(), out.size(), 3);
        return out;
    }
    const std::string bytes = internal::load_file(path);
    PointSet out = internal::read_delimited_points(path, bytes, ext == ".csv");
    internal::check_coordinate_range(path, out.coordinates.data(), out.size(), out.dimension);
    return out;
}

}  // namespace tapeline
