// OFF reader (Geomview object file format): "OFF" with optional ST/C/N prefixes (texture
// coordinates, colours, normals after x y z are ignored), '#' comments, one vertex or face per
// line.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io_types.h>

#include <string>
#include <string_view>

namespace tapeline::internal {

/// Next line with content (comments stripped); false at the end of the file.
inline bool next_content_line(LineScanner& lines, std::string_view& line) {
    while (lines.next(line)) {
        line = strip_comment(line);
        if (!is_blank(line)) {
            return true;
        }
    }
    return false;
}

inline PolygonSoup read_off(const std::string& path, std::string_view text) {
    PolygonSoup soup;
    soup.file = path;
    soup.format = "off";
    LineScanner lines(text);
    std::string_view line, token;
    if (!next_content_line(lines, line)) {
        throw InvalidInput(path + ": no OFF header (file has only comments or blanks)");
    }
    Tokens header(line);
    header.next(token);
    {
        std::string_view key = token;
        if (key.substr(0, 2) == "ST") {
            key.remove_prefix(2);
        }
        for (char flag : {'C', 'N'}) {
            if (!key.empty() && key.front() == flag) {
                key.remove_prefix(1);
            }
        }
        if (key == "4OFF" || key == "nOFF" || key == "4nOFF") {
            throw InvalidInput(path + ": " + at_line(lines.line_number()) + "OFF variant " +
                               quoted(token) +
                               " (homogeneous or n-dimensional coordinates) is not supported");
        }
        if (key != "OFF") {
            throw InvalidInput(path + ": " + at_line(lines.line_number()) +
                               "expected the OFF header keyword, found " + quoted(token));
        }
    }
    // Counts follow the keyword on the same line or on the next line with content.
    Tokens counts_tokens = header;
    std::string_view first;
    if (!counts_tokens.next(first)) {
        if (!next_content_line(lines, line)) {
            throw InvalidInput(path + ": truncated: file ends before the vertex and face counts");
        }
        counts_tokens = Tokens(line);
        counts_tokens.next(first);
    }
    if (first == "BINARY") {
        throw InvalidInput(path + ": " + at_line(lines.line_number()) +
                           "binary OFF is not supported (convert it to ASCII OFF or to PLY)");
    }
    long long counts[3] = {0, 0, 0};
    int n_counts = 0;
    for (std::string_view t = first; n_counts < 3;) {
        if (!parse_integer(t, counts[n_counts]) || counts[n_counts] < 0) {
            throw InvalidInput(path + ": " + at_line(lines.line_number()) + "cannot parse " +
                               quoted(t) + " as a vertex, face or edge count");
        }
        ++n_counts;
        if (!counts_tokens.next(t)) {
            break;
        }
    }
    if (n_counts < 2) {
        throw InvalidInput(path + ": " + at_line(lines.line_number()) +
                           "expected vertex and face counts after the OFF keyword");
    }
    const auto nv = static_cast<std::size_t>(counts[0]);
    const auto nf = static_cast<std::size_t>(counts[1]);
    soup.points.reserve(safe_reserve(nv, text.size(), 6));
    soup.point_lines.reserve(soup.points.capacity());
    for (std::size_t i = 0; i < nv; ++i) {
        if (!next_content_line(lines, line)) {
            throw InvalidInput(path + ": truncated: header announces " + std::to_string(nv) +
                               " vertices, file ends after " + std::to_string(i));
        }
        Tokens tokens(line);
        const std::array<double, 3> p = read_xyz(tokens, path, lines.line_number(), i);
        soup.points.push_back(p);
        soup.point_lines.push_back(lines.line_number());
    }
    soup.faces.reserve(safe_reserve(nf, text.size(), 8));
    soup.face_lines.reserve(soup.faces.capacity());
    for (std::size_t f = 0; f < nf; ++f) {
        if (!next_content_line(lines, line)) {
            throw InvalidInput(path + ": truncated: header announces " + std::to_string(nf) +
                               " faces, file ends after " + std::to_string(f));
        }
        const std::string where =
            path + ": " + at_line(lines.line_number()) + "face " + std::to_string(f);
        Tokens tokens(line);
        long long n = 0;
        tokens.next(token);
        if (!parse_integer(token, n) || n < 0) {
            throw InvalidInput(where + ": cannot parse " + quoted(token) + " as a vertex count");
        }
        if (n < 3) {
            throw InvalidInput(where + " has only " + std::to_string(n) +
                               " vertices (a face needs at least 3)");
        }
        std::vector<std::size_t> face;
        face.reserve(static_cast<std::size_t>(std::min<long long>(n, 64)));
        for (long long k = 0; k < n; ++k) {
            long long index = 0;
            if (!tokens.next(token)) {
                throw InvalidInput(where + " announces " + std::to_string(n) +
                                   " vertices but lists " + std::to_string(k));
            }
            if (!parse_integer(token, index)) {
                throw InvalidInput(where + ": cannot parse " + quoted(token) +
                                   " as a vertex index");
            }
            if (index < 0 || static_cast<unsigned long long>(index) >= nv) {
                throw InvalidInput(where + " references vertex " + std::to_string(index) +
                                   " but there are " + std::to_string(nv) + " vertices");
            }
            face.push_back(static_cast<std::size_t>(index));
        }
        soup.faces.push_back(std::move(face));
        soup.face_lines.push_back(lines.line_number());
    }
    return soup;
}

}  // namespace tapeline::internal
