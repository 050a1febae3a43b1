// PLY reader (Turk's polygon file format): ascii, binary_little_endian and binary_big_endian;
// any elements and properties in the header. The `vertex` element needs scalar x, y, z; the
// `face` element needs a list property `vertex_indices` (or `vertex_index`). Other elements are
// skipped; other scalar vertex properties are kept in PolygonSoup::vertex_properties.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/text_scan.h>
#include <tapeline/core/mesh_io_types.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace tapeline::internal {

enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };

inline bool ply_type_from_name(std::string_view name, PlyType& type) {
    static const std::pair<const char*, PlyType> names[] = {
        {"char", PlyType::i8},     {"int8", PlyType::i8},     {"uchar", PlyType::u8},
        {"uint8", PlyType::u8},    {"short", PlyType::i16},   {"int16", PlyType::i16},
        {"ushort", PlyType::u16},  {"uint16", PlyType::u16},  {"int", PlyType::i32},
        {"int32", PlyType::i32},   {"uint", PlyType::u32},    {"uint32", PlyType::u32},
        {"float", PlyType::f32},   {"float32", PlyType::f32}, {"double", PlyType::f64},
        {"float64", PlyType::f64},
    };
    for (const auto& [n, t] : names) {
        if (name == n) {
            type = t;
            return true;
        }
    }
    return false;
}

inline std::size_t ply_type_size(PlyType t) {
    switch (t) {
        case PlyType::i8:
        case PlyType::u8:
            return 1;
        case PlyType::i16:
        case PlyType::u16:
            return 2;
        case PlyType::i32:
        case PlyType::u32:
        case PlyType::f32:
            return 4;
        case PlyType::f64:
            return 8;
    }
    return 0;
}

inline bool ply_is_integer(PlyType t) {
    return t != PlyType::f32 && t != PlyType::f64;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::f32;  // item type for lists
    bool is_list = false;
    PlyType count_type = PlyType::u8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

inline bool host_is_little_endian() {
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

/// `v` rounded to float and back. Through a volatile: g++ 12.2 at -O2/-O3 was seen to drop a
/// plain (and a memcpy-based) double->float->double round trip when it vectorises the caller.
inline double round_to_float(double v) {
    volatile float f = static_cast<float>(v);
    return f;
}

/// Reads one binary value of type `t` at `p` (bounds already checked), as double.
inline double ply_binary_value(const char* p, PlyType t, bool swap) {
    unsigned char b[8];
    const std::size_t n = ply_type_size(t);
    std::memcpy(b, p, n);
    if (swap) {
        for (std::size_t i = 0; i < n / 2; ++i) {
            std::swap(b[i], b[n - 1 - i]);
        }
    }
    switch (t) {
        case PlyType::i8: {
            std::int8_t v;
            std::memcpy(&v, b, 1);
            return v;
        }
        case PlyType::u8:
            return b[0];
        case PlyType::i16: {
            std::int16_t v;
            std::memcpy(&v, b, 2);
            return v;
        }
        case PlyType::u16: {
            std::uint16_t v;
            std::memcpy(&v, b, 2);
            return v;
        }
        case PlyType::i32: {
            std::int32_t v;
            std::memcpy(&v, b, 4);
            return v;
        }
        case PlyType::u32: {
            std::uint32_t v;
            std::memcpy(&v, b, 4);
            return v;
        }
        case PlyType::f32: {
            float v;
            std::memcpy(&v, b, 4);
            return v;
        }
        case PlyType::f64: {
            double v;
            std::memcpy(&v, b, 8);
            return v;
        }
    }
    return 0;
}

inline std::string ply_plural(const std::string& element) {
    if (element == "vertex") {
        return "vertices";
    }
    if (element == "face") {
        return "faces";
    }
    return "'" + element + "' elements";
}

/// Role of each property while reading: which coordinate, which extra vertex scalar, the face
/// index list, or nothing.
struct PlyRoles {
    std::vector<int> vertex_role;  // 0,1,2 = x,y,z; 3+k = extra scalar k; -1 = skip
    std::vector<std::string> extra_names;
    int face_list = -1;  // property index of the face's index list
};

inline PolygonSoup read_ply(const std::string& path, std::string_view text) {
    PolygonSoup soup;
    soup.file = path;
    LineScanner lines(text);
    std::string_view line, token;
    if (!lines.next(line) || line != "ply") {
        throw InvalidInput(path + ": not a PLY file (the first line is not 'ply')");
    }
    std::vector<PlyElement> elements;
    bool have_format = false, ended = false, binary = false, big_endian = false;
    while (lines.next(line)) {
        const std::string where = path + ": " + at_line(lines.line_number());
        Tokens tokens(line);
        if (!tokens.next(token)) {
            continue;
        }
        if (token == "comment" || token == "obj_info") {
            continue;
        }
        if (token == "end_header") {
            ended = true;
            break;
        }
        if (token == "format") {
            tokens.next(token);
            if (token == "ascii") {
                soup.format = "ply-ascii";
            } else if (token == "binary_little_endian") {
                soup.format = "ply-binary-le";
                binary = true;
            } else if (token == "binary_big_endian") {
                soup.format = "ply-binary-be";
                binary = true;
                big_endian = true;
            } else {
                throw InvalidInput(where + "unknown PLY format " + quoted(token));
            }
            have_format = true;
        } else if (token == "element") {
            PlyElement e;
            long long count = -1;
            std::string_view count_text;
            if (!tokens.next(token) || !tokens.next(count_text) ||
                !parse_integer(count_text, count) || count < 0) {
                throw InvalidInput(where +
                                   "malformed element line (expected 'element <name> "
                                   "<count>')");
            }
            e.name = std::string(token);
            e.count = static_cast<std::uint64_t>(count);
            elements.push_back(std::move(e));
        } else if (token == "property") {
            if (elements.empty()) {
                throw InvalidInput(where + "property before any element");
            }
            PlyProperty p;
            std::string_view type_name;
            if (!tokens.next(type_name)) {
                throw InvalidInput(where + "malformed property line");
            }
            if (type_name == "list") {
                std::string_view count_type, item_type;
                if (!tokens.next(count_type) || !tokens.next(item_type)) {
                    throw InvalidInput(where + "malformed list property line");
                }
                p.is_list = true;
                if (!ply_type_from_name(count_type, p.count_type) ||
                    !ply_is_integer(p.count_type)) {
                    throw InvalidInput(where + "unknown or non-integer list count type " +
                                       quoted(count_type));
                }
                type_name = item_type;
            }
            if (!ply_type_from_name(type_name, p.type)) {
                throw InvalidInput(where + "unknown property type " + quoted(type_name));
            }
            if (!tokens.next(token)) {
                throw InvalidInput(where + "property without a name");
            }
            p.name = std::string(token);
            elements.back().properties.push_back(std::move(p));
        } else {
            throw InvalidInput(where + "unexpected header keyword " + quoted(token));
        }
    }
    if (!ended) {
        throw InvalidInput(path + ": truncated: the PLY header has no 'end_header' line");
    }
    if (!have_format) {
        throw InvalidInput(path + ": the PLY header has no 'format' line");
    }

    // Find what we need.
    std::uint64_t nv = 0;
    const PlyElement* vertex_element = nullptr;
    PlyRoles roles;
    for (const PlyElement& e : elements) {
        if (e.name == "vertex") {
            vertex_element = &e;
            nv = e.count;
            roles.vertex_role.assign(e.properties.size(), -1);
            int found[3] = {-1, -1, -1};
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const PlyProperty& p = e.properties[k];
                if (p.is_list) {
                    continue;
                }
                const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
                if (axis >= 0) {
                    roles.vertex_role[k] = axis;
                    found[axis] = static_cast<int>(k);
                } else {
                    roles.vertex_role[k] = 3 + static_cast<int>(roles.extra_names.size());
                    roles.extra_names.push_back(p.name);
                }
            }
            for (int axis = 0; axis < 3; ++axis) {
                if (found[axis] < 0) {
                    throw InvalidInput(path + ": the PLY vertex element has no scalar '" +
                                       std::string(1, "xyz"[axis]) + "' property");
                }
            }
        } else if (e.name == "face") {
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const PlyProperty& p = e.properties[k];
                if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
                    if (!ply_is_integer(p.type)) {
                        throw InvalidInput(path + ": the PLY face list '" + p.name +
                                           "' has a non-integer item type");
                    }
                    roles.face_list = static_cast<int>(k);
                }
            }
            if (roles.face_list < 0) {
                throw InvalidInput(path +
                                   ": the PLY face element has no 'vertex_indices' list property");
            }
        }
    }
    if (vertex_element == nullptr) {
        throw InvalidInput(path + ": the PLY header declares no vertex element");
    }
    soup.points.reserve(safe_reserve(nv, text.size(), 3));
    std::vector<std::vector<double>> extras(roles.extra_names.size());
    for (auto& x : extras) {
        x.reserve(soup.points.capacity());
    }

    auto add_face_index = [&](std::vector<std::size_t>& face, long long index, std::size_t f,
                              const std::string& where) {
        if (index < 0 || static_cast<unsigned long long>(index) >= nv) {
            throw InvalidInput(where + "face " + std::to_string(f) + " references vertex " +
                               std::to_string(index) + " but there are " + std::to_string(nv) +
                               " vertices");
        }
        face.push_back(static_cast<std::size_t>(index));
    };

    if (binary) {
        const bool swap = big_endian == host_is_little_endian();
        const char* p = text.data() + lines.position();
        const char* const end = text.data() + text.size();
        if (lines.position() > text.size()) {
            p = end;
        }
        const std::string prefix = path + ": ";
        for (const PlyElement& e : elements) {
            const bool is_vertex = &e == vertex_element;
            const bool is_face = e.name == "face";
            if (is_face) {
                soup.faces.reserve(safe_reserve(e.count, text.size(), 4));
            }
            for (std::uint64_t i = 0; i < e.count; ++i) {
                std::array<double, 3> xyz{};
                std::vector<std::size_t> face;
                for (std::size_t k = 0; k < e.properties.size(); ++k) {
                    const PlyProperty& prop = e.properties[k];
                    auto truncated = [&]() {
                        return InvalidInput(prefix + "truncated: header announces " +
                                            std::to_string(e.count) + " " + ply_plural(e.name) +
                                            ", file ends after " + std::to_string(i));
                    };
                    if (!prop.is_list) {
                        const std::size_t size = ply_type_size(prop.type);
                        if (static_cast<std::size_t>(end - p) < size) {
                            throw truncated();
                        }
                        if (is_vertex && roles.vertex_role[k] >= 0) {
                            const double v = ply_binary_value(p, prop.type, swap);
                            const int role = roles.vertex_role[k];
                            if (role < 3) {
                                xyz[role] = v;
                            } else {
                                extras[role - 3].push_back(v);
                            }
                        }
                        p += size;
                        continue;
                    }
                    const std::size_t count_size = ply_type_size(prop.count_type);
                    if (static_cast<std::size_t>(end - p) < count_size) {
                        throw truncated();
                    }
                    const double count_value = ply_binary_value(p, prop.count_type, swap);
                    p += count_size;
                    if (count_value < 0) {
                        throw InvalidInput(prefix + e.name + " " + std::to_string(i) +
                                           ": negative list length");
                    }
                    const auto n = static_cast<std::size_t>(count_value);
                    const std::size_t item = ply_type_size(prop.type);
                    if (static_cast<std::size_t>(end - p) / item < n) {
                        throw truncated();
                    }
                    if (is_face && static_cast<int>(k) == roles.face_list) {
                        if (n < 3) {
                            throw InvalidInput(prefix + "face " + std::to_string(i) + " has only " +
                                               std::to_string(n) +
                                               " vertices (a face needs at least 3)");
                        }
                        face.reserve(n);
                        for (std::size_t c = 0; c < n; ++c) {
                            add_face_index(face,
                                           static_cast<long long>(
                                               ply_binary_value(p + c * item, prop.type, swap)),
                                           static_cast<std::size_t>(i), prefix);
                        }
                    }
                    p += n * item;
                }
                if (is_vertex) {
                    if (const char* bad = non_finite_kind(xyz[0], xyz[1], xyz[2]); *bad) {
                        throw InvalidInput(prefix + "vertex " + std::to_string(i) + " has " + bad);
                    }
                    soup.points.push_back(xyz);
                } else if (is_face) {
                    soup.faces.push_back(std::move(face));
                }
            }
        }
    } else {
        // ASCII: whitespace-separated values, usually one element per line; track lines.
        LineScanner data(text, lines.position(), lines.line_number() + 1);
        std::string_view data_line;
        Tokens tokens{std::string_view()};
        auto next_token = [&](std::string_view& t) {
            while (!tokens.next(t)) {
                if (!data.next(data_line)) {
                    return false;
                }
                tokens = Tokens(data_line);
            }
            return true;
        };
        for (const PlyElement& e : elements) {
            const bool is_vertex = &e == vertex_element;
            const bool is_face = e.name == "face";
            for (std::uint64_t i = 0; i < e.count; ++i) {
                std::array<double, 3> xyz{};
                std::vector<std::size_t> face;
                std::uint32_t first_line = 0;
                for (std::size_t k = 0; k < e.properties.size(); ++k) {
                    const PlyProperty& prop = e.properties[k];
                    std::string_view t;
                    auto need = [&](std::string_view& out) {
                        if (!next_token(out)) {
                            throw InvalidInput(path + ": truncated: header announces " +
                                               std::to_string(e.count) + " " + ply_plural(e.name) +
                                               ", file ends after " + std::to_string(i));
                        }
                        if (first_line == 0) {
                            first_line = data.line_number();
                        }
                    };
                    auto where = [&]() {
                        return path + ": " + at_line(data.line_number()) + e.name + " " +
                               std::to_string(i);
                    };
                    need(t);
                    if (!prop.is_list) {
                        if (is_vertex && roles.vertex_role[k] >= 0) {
                            double v = 0;
                            if (!parse_double(t, v)) {
                                throw InvalidInput(where() + ": cannot parse " + quoted(t) +
                                                   " as a number");
                            }
                            if (prop.type == PlyType::f32) {
                                v = round_to_float(v);  // the value the header declares
                            }
                            const int role = roles.vertex_role[k];
                            if (role < 3) {
                                xyz[role] = v;
                            } else {
                                extras[role - 3].push_back(v);
                            }
                        }
                        continue;
                    }
                    long long n = 0;
                    if (!parse_integer(t, n) || n < 0) {
                        throw InvalidInput(where() + ": cannot parse " + quoted(t) +
                                           " as a list length");
                    }
                    const bool indices = is_face && static_cast<int>(k) == roles.face_list;
                    if (indices && n < 3) {
                        throw InvalidInput(where() + " has only " + std::to_string(n) +
                                           " vertices (a face needs at least 3)");
                    }
                    for (long long c = 0; c < n; ++c) {
                        need(t);
                        if (indices) {
                            long long index = 0;
                            if (!parse_integer(t, index)) {
                                throw InvalidInput(where() + ": cannot parse " + quoted(t) +
                                                   " as a vertex index");
                            }
                            add_face_index(face, index, static_cast<std::size_t>(i),
                                           path + ": " + at_line(data.line_number()));
                        }
                    }
                }
                if (is_vertex) {
                    if (const char* bad = non_finite_kind(xyz[0], xyz[1], xyz[2]); *bad) {
                        throw InvalidInput(path + ": " + at_line(first_line) + "vertex " +
                                           std::to_string(i) + " has " + bad);
                    }
                    soup.points.push_back(xyz);
                    soup.point_lines.push_back(first_line);
                } else if (is_face) {
                    soup.faces.push_back(std::move(face));
                    soup.face_lines.push_back(first_line);
                }
            }
        }
    }
    for (std::size_t k = 0; k < extras.size(); ++k) {
        soup.vertex_properties[roles.extra_names[k]] = std::move(extras[k]);
    }
    return soup;
}

}  // namespace tapeline::internal
