// STL reader, ASCII and binary. STL stores every facet with its own corner coordinates, so
// corners with exactly equal coordinates are shared while reading: vertex i is the i-th distinct
// point in order of first appearance, face i is facet i.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io_types.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>

namespace tapeline::internal {

/// Hash of a point by its exact coordinates (-0.0 and 0.0 are the same point).
struct ExactPointHash {
    std::size_t operator()(const std::array<double, 3>& p) const {
        std::size_t h = 0;
        for (double c : p) {
            if (c == 0.0) {
                c = 0.0;
            }
            std::uint64_t bits;
            std::memcpy(&bits, &c, sizeof bits);
            h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        }
        return h;
    }
};

/// Assigns indices to distinct points in order of first appearance.
class PointWelder {
public:
    explicit PointWelder(PolygonSoup& soup) : soup_(soup) {}
    std::size_t index_of(const std::array<double, 3>& p, std::uint32_t line) {
        const auto [it, inserted] = map_.emplace(p, soup_.points.size());
        if (inserted) {
            soup_.points.push_back(p);
            if (line != 0) {
                soup_.point_lines.push_back(line);
            }
        }
        return it->second;
    }

private:
    PolygonSoup& soup_;
    std::unordered_map<std::array<double, 3>, std::size_t, ExactPointHash> map_;
};

inline PolygonSoup read_stl_ascii(const std::string& path, std::string_view text) {
    PolygonSoup soup;
    soup.file = path;
    soup.format = "stl-ascii";
    PointWelder welder(soup);
    LineScanner lines(text);
    std::string_view line, token;
    bool in_solid = false, in_facet = false, ended = false;
    std::uint32_t facet_line = 0;
    std::vector<std::size_t> face;
    while (lines.next(line)) {
        Tokens tokens(line);
        if (!tokens.next(token)) {
            continue;
        }
        const std::string where = path + ": " + at_line(lines.line_number());
        const std::string facet_name = "facet " + std::to_string(soup.faces.size());
        if (token == "solid") {
            if (in_solid) {
                throw InvalidInput(where + "'solid' inside another solid");
            }
            in_solid = true;
            ended = false;
        } else if (token == "endsolid") {
            if (in_facet) {
                throw InvalidInput(where + "'endsolid' inside " + facet_name);
            }
            in_solid = false;
            ended = true;
        } else if (!in_solid) {
            throw InvalidInput(where + "unexpected " + quoted(token) + " outside 'solid'");
        } else if (token == "facet") {
            if (in_facet) {
                throw InvalidInput(where + "'facet' inside " + facet_name);
            }
            in_facet = true;
            facet_line = lines.line_number();
            face.clear();
        } else if (token == "outer" || token == "endloop") {
            if (!in_facet) {
                throw InvalidInput(where + "unexpected " + quoted(token) + " outside a facet");
            }
        } else if (token == "vertex") {
            if (!in_facet) {
                throw InvalidInput(where + "'vertex' outside a facet");
            }
            std::array<double, 3> p{};
            for (int k = 0; k < 3; ++k) {
                if (!tokens.next(token) || !parse_double(token, p[k])) {
                    throw InvalidInput(where + facet_name + ", corner " +
                                       std::to_string(face.size()) + ": cannot parse " +
                                       quoted(token) + " as a number");
                }
            }
            if (const char* bad = non_finite_kind(p[0], p[1], p[2]); *bad) {
                throw InvalidInput(where + facet_name + ", corner " + std::to_string(face.size()) +
                                   " has " + bad);
            }
            face.push_back(welder.index_of(p, lines.line_number()));
        } else if (token == "endfacet") {
            if (!in_facet) {
                throw InvalidInput(where + "'endfacet' outside a facet");
            }
            if (face.size() < 3) {
                throw InvalidInput(where + facet_name + " has only " + std::to_string(face.size()) +
                                   " vertices (a face needs at least 3)");
            }
            in_facet = false;
            soup.faces.push_back(face);
            soup.face_lines.push_back(facet_line);
        } else {
            throw InvalidInput(where + "unexpected " + quoted(token) + " in ASCII STL");
        }
    }
    if (in_facet) {
        throw InvalidInput(path + ": truncated: file ends inside facet " +
                           std::to_string(soup.faces.size()) + " (started on line " +
                           std::to_string(facet_line) + ")");
    }
    if (!ended) {
        throw InvalidInput(path + ": truncated: file ends without 'endsolid' after " +
                           std::to_string(soup.faces.size()) + " facets");
    }
    return soup;
}

inline std::uint32_t read_u32_le(const char* p) {
    const auto* b = reinterpret_cast<const unsigned char*>(p);
    return static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
           (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}

inline float read_f32_le(const char* p) {
    const std::uint32_t bits = read_u32_le(p);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

inline PolygonSoup read_stl_binary(const std::string& path, std::string_view bytes) {
    PolygonSoup soup;
    soup.file = path;
    soup.format = "stl-binary";
    if (bytes.size() < 84) {
        throw InvalidInput(path + ": truncated: " + std::to_string(bytes.size()) +
                           " bytes is too short for a binary STL (84-byte header needed) and it "
                           "is not ASCII STL (no 'solid' keyword)");
    }
    const std::uint64_t n = read_u32_le(bytes.data() + 80);
    const std::uint64_t expected = 84 + 50 * n;
    if (bytes.size() < expected) {
        throw InvalidInput(path + ": truncated: header announces " + std::to_string(n) +
                           " triangles (" + std::to_string(expected) + " bytes), file ends after " +
                           std::to_string((bytes.size() - 84) / 50));
    }
    if (bytes.size() > expected) {
        throw InvalidInput(path + ": binary STL header announces " + std::to_string(n) +
                           " triangles (" + std::to_string(expected) + " bytes) but the file has " +
                           std::to_string(bytes.size()) + " bytes");
    }
    PointWelder welder(soup);
    soup.faces.reserve(n);
    const char* p = bytes.data() + 84;
    for (std::uint64_t f = 0; f < n; ++f, p += 50) {
        std::vector<std::size_t> face(3);
        for (int c = 0; c < 3; ++c) {
            const char* q = p + 12 + 12 * c;
            const std::array<double, 3> x = {read_f32_le(q), read_f32_le(q + 4),
                                             read_f32_le(q + 8)};
            if (const char* bad = non_finite_kind(x[0], x[1], x[2]); *bad) {
                throw InvalidInput(path + ": facet " + std::to_string(f) + ", corner " +
                                   std::to_string(c) + " has " + bad);
            }
            face[c] = welder.index_of(x, 0);
        }
        soup.faces.push_back(std::move(face));
    }
    return soup;
}

inline PolygonSoup read_stl(const std::string& path, std::string_view bytes) {
    if (bytes.size() >= 84 &&
        84 + 50 * std::uint64_t{read_u32_le(bytes.data() + 80)} == bytes.size()) {
        return read_stl_binary(path, bytes);
    }
    std::size_t start = 0;
    while (start < bytes.size() && is_space(bytes[start])) {
        ++start;
    }
    if (bytes.substr(start, 5) == "solid") {
        return read_stl_ascii(path, bytes);
    }
    return read_stl_binary(path, bytes);
}

}  // namespace tapeline::internal
