// A minimal, strict XML reader for small documents (Seamly2D measurement files, our own SVG).
//
// Supports: the XML declaration and processing instructions (skipped), comments, elements with
// single- or double-quoted attributes, text, CDATA, the five predefined entities and numeric
// character references. Rejects, with the line and column: DOCTYPE (no entity definitions to
// expand), mismatched or unclosed tags, duplicate attributes, unknown entities, text after the
// root element. Namespaces are not interpreted ("svg:g" is just a name). No dependency; the
// documents we read are small, so the tree is built in memory.
#pragma once

#include <tapeline/core/errors.h>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tapeline::xml {

/// One element of a parsed XML document and its subtree.
struct Element {
    std::string name;                               ///< tag name
    std::map<std::string, std::string> attributes;  ///< attributes by name
    std::vector<Element> children;                  ///< child elements in document order
    std::string text;      ///< concatenated character data directly inside this element
    std::size_t line = 0;  ///< 1-based line of the start tag

    /// Attribute value or nullptr.
    const std::string* attribute(const std::string& key) const {
        const auto it = attributes.find(key);
        return it == attributes.end() ? nullptr : &it->second;
    }
    /// First child element named `child`, or nullptr.
    const Element* child(const std::string& child_name) const {
        for (const Element& c : children) {
            if (c.name == child_name) {
                return &c;
            }
        }
        return nullptr;
    }
};

/// Deepest element nesting accepted: measurement files and our SVG stay under 10 levels, and both
/// the parser and the tree's destructor recurse once per level.
inline constexpr std::size_t max_depth = 256;

namespace internal {

class Parser {
public:
    Parser(const std::string& text, std::string source) : s_(text), source_(std::move(source)) {}

    Element parse_document() {
        skip_misc();
        if (at_end() || s_[pos_] != '<') {
            fail("expected the root element");
        }
        if (starts("<!DOCTYPE") || starts("<!doctype")) {
            fail("DOCTYPE is not supported");
        }
        Element root = parse_element();
        skip_misc();
        if (!at_end()) {
            fail("content after the root element");
        }
        return root;
    }

private:
    const std::string& s_;
    std::string source_;
    std::size_t pos_ = 0;
    std::size_t line_ = 1;
    std::size_t line_start_ = 0;
    std::size_t depth_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw InvalidInput(source_ + ":" + std::to_string(line_) + ":" +
                           std::to_string(pos_ - line_start_ + 1) + ": XML: " + what);
    }
    bool at_end() const { return pos_ >= s_.size(); }
    bool starts(const char* lit) const {
        return s_.compare(pos_, std::string(lit).size(), lit) == 0;
    }
    void advance(std::size_t n = 1) {
        for (std::size_t i = 0; i < n && pos_ < s_.size(); ++i, ++pos_) {
            if (s_[pos_] == '\n') {
                ++line_;
                line_start_ = pos_ + 1;
            }
        }
    }
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
    static bool is_name_char(char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
               c == ':' || static_cast<unsigned char>(c) >= 0x80;
    }
    void skip_space() {
        while (!at_end() && is_space(s_[pos_])) {
            advance();
        }
    }
    void skip_until(const char* end, const char* what) {
        const std::size_t e = s_.find(end, pos_);
        if (e == std::string::npos) {
            fail(std::string("unterminated ") + what);
        }
        advance(e + std::string(end).size() - pos_);
    }
    /// Whitespace, comments and processing instructions between top-level items.
    void skip_misc() {
        for (;;) {
            skip_space();
            if (starts("<?")) {
                skip_until("?>", "processing instruction");
            } else if (starts("<!--")) {
                skip_until("-->", "comment");
            } else {
                return;
            }
        }
    }
    std::string parse_name() {
        const std::size_t b = pos_;
        while (!at_end() && is_name_char(s_[pos_])) {
            advance();
        }
        if (b == pos_) {
            fail("expected a name");
        }
        return s_.substr(b, pos_ - b);
    }
    static void append_utf8(std::string& out, std::uint32_t cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }
    void parse_reference(std::string& out) {
        const std::size_t semi = s_.find(';', pos_);
        if (semi == std::string::npos || semi - pos_ > 12) {
            fail("unterminated entity reference");
        }
        const std::string ent = s_.substr(pos_ + 1, semi - pos_ - 1);
        if (ent == "lt") {
            out += '<';
        } else if (ent == "gt") {
            out += '>';
        } else if (ent == "amp") {
            out += '&';
        } else if (ent == "quot") {
            out += '"';
        } else if (ent == "apos") {
            out += '\'';
        } else if (ent.size() > 1 && ent[0] == '#') {
            const bool hex = ent[1] == 'x';
            const std::string digits = ent.substr(hex ? 2 : 1);
            std::size_t used = 0;
            unsigned long cp = 0;
            try {
                cp = std::stoul(digits, &used, hex ? 16 : 10);
            } catch (...) {
                used = 0;
            }
            if (digits.empty() || used != digits.size() || cp == 0 || cp > 0x10FFFF) {
                fail("bad character reference '&" + ent + ";'");
            }
            append_utf8(out, static_cast<std::uint32_t>(cp));
        } else {
            fail("unknown entity '&" + ent + ";'");
        }
        advance(semi + 1 - pos_);
    }
    Element parse_element() {
        Element el;
        el.line = line_;
        advance();  // '<'
        el.name = parse_name();
        for (;;) {
            const std::size_t before = pos_;
            skip_space();
            if (at_end()) {
                fail("unterminated start tag <" + el.name + ">");
            }
            if (starts("/>")) {
                advance(2);
                return el;
            }
            if (s_[pos_] == '>') {
                advance();
                break;
            }
            if (before == pos_) {
                fail("expected whitespace before an attribute in <" + el.name + ">");
            }
            const std::string key = parse_name();
            skip_space();
            if (at_end() || s_[pos_] != '=') {
                fail("attribute '" + key + "' of <" + el.name + "> has no value");
            }
            advance();
            skip_space();
            if (at_end() || (s_[pos_] != '"' && s_[pos_] != '\'')) {
                fail("attribute '" + key + "' of <" + el.name + "> is not quoted");
            }
            const char q = s_[pos_];
            advance();
            std::string value;
            while (!at_end() && s_[pos_] != q) {
                if (s_[pos_] == '<') {
                    fail("'<' in attribute '" + key + "'");
                }
                if (s_[pos_] == '&') {
                    parse_reference(value);
                } else {
                    value += s_[pos_];
                    advance();
                }
            }
            if (at_end()) {
                fail("unterminated attribute '" + key + "' of <" + el.name + ">");
            }
            advance();
            if (!el.attributes.emplace(key, value).second) {
                fail("duplicate attribute '" + key + "' in <" + el.name + ">");
            }
        }
        // Content.
        for (;;) {
            if (at_end()) {
                fail("element <" + el.name + "> (line " + std::to_string(el.line) +
                     ") is not closed");
            }
            if (starts("</")) {
                advance(2);
                const std::string end = parse_name();
                if (end != el.name) {
                    fail("</" + end + "> closes <" + el.name + "> (line " +
                         std::to_string(el.line) + ")");
                }
                skip_space();
                if (at_end() || s_[pos_] != '>') {
                    fail("expected '>' after </" + end);
                }
                advance();
                return el;
            }
            if (starts("<!--")) {
                skip_until("-->", "comment");
            } else if (starts("<![CDATA[")) {
                advance(9);
                const std::size_t e = s_.find("]]>", pos_);
                if (e == std::string::npos) {
                    fail("unterminated CDATA section");
                }
                el.text += s_.substr(pos_, e - pos_);
                advance(e + 3 - pos_);
            } else if (starts("<?")) {
                skip_until("?>", "processing instruction");
            } else if (starts("<!")) {
                fail("unexpected markup declaration");
            } else if (s_[pos_] == '<') {
                if (++depth_ >= max_depth) {
                    fail("elements nested deeper than " + std::to_string(max_depth) + " levels");
                }
                el.children.push_back(parse_element());
                --depth_;
            } else if (s_[pos_] == '&') {
                parse_reference(el.text);
            } else {
                el.text += s_[pos_];
                advance();
            }
        }
    }
};

}  // namespace internal

/// Parses a whole document; errors name `source`, line and column.
///
/// \throws InvalidInput on malformed XML, nesting deeper than max_depth, or a DOCTYPE.
inline Element parse(const std::string& text, const std::string& source) {
    return internal::Parser(text, source).parse_document();
}

}  // namespace tapeline::xml
