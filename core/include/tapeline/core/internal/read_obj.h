// Wavefront OBJ reader: `v` and `f` records only (vt, vn, l, g, usemtl, ... are skipped). Face
// corners may be `a`, `a/b`, `a/b/c` or `a//c`; negative indices count back from the last vertex
// defined so far. Vertices are numbered from 0 in the API (the file's `1` is vertex 0).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io_types.h>

#include <string>
#include <string_view>

namespace tapeline::internal {

inline PolygonSoup read_obj(const std::string& path, std::string_view text) {
    PolygonSoup soup;
    soup.file = path;
    soup.format = "obj";
    LineScanner lines(text);
    std::string_view line, token;
    // Positive indices may refer to vertices defined later in the file; they are checked at the
    // end, with the line and the number as written.
    struct Forward {
        std::size_t face, corner;
        long long written;
    };
    std::vector<Forward> forward;
    while (lines.next(line)) {
        Tokens tokens(strip_comment(line));
        if (!tokens.next(token)) {
            continue;
        }
        if (token == "v") {
            const std::size_t i = soup.points.size();
            const std::array<double, 3> p = read_xyz(tokens, path, lines.line_number(), i);
            soup.points.push_back(p);
            soup.point_lines.push_back(lines.line_number());
        } else if (token == "f" || token == "fo") {
            const std::size_t f = soup.faces.size();
            const std::string where =
                path + ": " + at_line(lines.line_number()) + "face " + std::to_string(f);
            std::vector<std::size_t> face;
            while (tokens.next(token)) {
                const std::string_view index_text = token.substr(0, token.find('/'));
                long long index = 0;
                if (!parse_integer(index_text, index)) {
                    throw InvalidInput(where + ": cannot parse " + quoted(token) +
                                       " as a vertex reference");
                }
                if (index == 0) {
                    throw InvalidInput(where +
                                       " references vertex 0 (OBJ vertex numbers start at 1)");
                }
                if (index < 0) {
                    const long long resolved = static_cast<long long>(soup.points.size()) + index;
                    if (resolved < 0) {
                        throw InvalidInput(where + " references vertex " + std::to_string(index) +
                                           " but only " + std::to_string(soup.points.size()) +
                                           " vertices are defined before it");
                    }
                    face.push_back(static_cast<std::size_t>(resolved));
                } else {
                    if (static_cast<unsigned long long>(index) > soup.points.size()) {
                        forward.push_back({f, face.size(), index});
                    }
                    face.push_back(static_cast<std::size_t>(index - 1));
                }
            }
            if (face.size() < 3) {
                throw InvalidInput(where + " has only " + std::to_string(face.size()) +
                                   " vertices (a face needs at least 3)");
            }
            soup.faces.push_back(std::move(face));
            soup.face_lines.push_back(lines.line_number());
        }
    }
    for (const Forward& ref : forward) {
        if (static_cast<unsigned long long>(ref.written) > soup.points.size()) {
            throw InvalidInput(path + ": " + at_line(soup.face_lines[ref.face]) + "face " +
                               std::to_string(ref.face) + " references vertex " +
                               std::to_string(ref.written) + " but the file defines " +
                               std::to_string(soup.points.size()) + " vertices");
        }
    }
    return soup;
}

}  // namespace tapeline::internal
