// Escaping text for XML attribute values and element content (SVG pictures, Seamly2D files).
#pragma once

#include <string>

namespace tapeline {

/// text with & < > " ' replaced by their XML entities.
inline std::string xml_escape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

}  // namespace tapeline
