// See map_parser.h. A hand-written single-pass lexer: e3m4 (3.2 MB) parses in about 15-20 ms.
#include "map/map_parser.h"

#include "map/input_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace obscura::map {

namespace {

class Lexer {
public:
    Lexer(std::string_view text, const std::string& file) : s_(text), file_(file) {}

    [[noreturn]] void fail(const std::string& problem, SourcePos at) const {
        throw MapError(file_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + problem);
    }
    [[noreturn]] void fail(const std::string& problem) const { fail(problem, pos()); }

    SourcePos pos() const { return {line_, static_cast<int>(i_ - lineStart_) + 1}; }

    // Skips whitespace and // comments; false at end of input.
    bool skip() {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == '\n') {
                ++i_;
                ++line_;
                lineStart_ = i_;
            } else if (c == ' ' || c == '\t' || c == '\r') {
                ++i_;
            } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
                while (i_ < s_.size() && s_[i_] != '\n') ++i_;
            } else {
                return true;
            }
        }
        return false;
    }

    char peek() {
        if (!skip()) return '\0';
        return s_[i_];
    }

    void expect(char c, const char* context) {
        if (peek() != c) {
            if (i_ >= s_.size()) fail(std::string("unexpected end of file, expected '") + c + "' " + context);
            fail(std::string("expected '") + c + "' " + context + ", found '" + errorText(std::string_view(&s_[i_], 1)) + "'");
        }
        ++i_;
    }

    // A quoted string. Escapes follow TrenchBroom: a quote preceded by an odd number of
    // backslashes is part of the value (and unescaped to '"'); other backslashes are kept as
    // written. A value ending in a backslash ("c:\\quake\\") is still closed when the quote is
    // the last thing on its line, as TrenchBroom's reader does.
    std::string quoted() {
        if (peek() != '"') fail("expected a quoted string");
        const SourcePos at = pos();
        ++i_;
        std::string out;
        for (;;) {
            if (i_ >= s_.size()) fail("unterminated string", at);
            const char c = s_[i_];
            if (c == '\n' || c == '\r') fail("unterminated string (newline inside quotes)", at);
            if (c == '"') {
                std::size_t slashes = 0;
                while (slashes < out.size() && out[out.size() - 1 - slashes] == '\\') ++slashes;
                if (slashes % 2 == 0 || quoteEndsLine(i_ + 1)) break;
                out.back() = '"';  // the escaping backslash becomes the quote
                ++i_;
                continue;
            }
            out += c;
            ++i_;
        }
        ++i_;
        return out;
    }

    // A bare word: texture names may hold * + / - . digits etc.; ends at whitespace.
    std::string word(const char* what) {
        if (!skip()) fail(std::string("unexpected end of file, expected ") + what);
        const std::size_t b = i_;
        while (i_ < s_.size() && s_[i_] != ' ' && s_[i_] != '\t' && s_[i_] != '\r' && s_[i_] != '\n') ++i_;
        if (i_ == b) fail(std::string("expected ") + what);
        return std::string(s_.substr(b, i_ - b));
    }

    // A number token (sign, digits, '.', exponent); std::from_chars is exact and locale-free.
    double number(const char* what) {
        if (!skip()) fail(std::string("unexpected end of file, expected ") + what);
        const SourcePos at = pos();
        const std::size_t b = i_;
        while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.' ||
                                  s_[i_] == '-' || s_[i_] == '+'))
            ++i_;
        const std::string_view tok = s_.substr(b, i_ - b);
        if (tok.empty()) {
            if (i_ >= s_.size()) fail(std::string("unexpected end of file, expected ") + what, at);
            fail(std::string("expected ") + what + ", found '" + errorText(std::string_view(&s_[i_], 1)) + "'", at);
        }
        const std::string_view digits = tok[0] == '+' ? tok.substr(1) : tok;  // from_chars rejects '+'
        double v = 0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
        if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(v))
            fail("'" + errorText(tok) + "' is not a number (" + what + ")", at);
        return v;
    }

    bool atEnd() { return !skip(); }

    // Skips a balanced { } block (for patchDef2 and friends); the opening brace is next.
    void skipBlock() {
        const SourcePos at = pos();
        int depth = 0;
        do {
            if (!skip()) fail("unexpected end of file inside a skipped block", at);
            const char c = s_[i_];
            if (c == '"') {
                quoted();
                continue;
            }
            if (c == '{') ++depth;
            if (c == '}') --depth;
            ++i_;
        } while (depth > 0);
    }

private:
    // True if only blanks (or a // comment) follow position j up to the end of its line.
    bool quoteEndsLine(std::size_t j) const {
        while (j < s_.size() && (s_[j] == ' ' || s_[j] == '\t')) ++j;
        return j >= s_.size() || s_[j] == '\n' || s_[j] == '\r' || (s_[j] == '/' && j + 1 < s_.size() && s_[j + 1] == '/');
    }

    std::string_view s_;
    const std::string& file_;
    std::size_t i_ = 0;
    std::size_t lineStart_ = 0;
    int line_ = 1;
};

Vec3 point(Lexer& lx) {
    lx.expect('(', "to open a face point");
    Vec3 p;
    p.x = lx.number("x coordinate");
    p.y = lx.number("y coordinate");
    p.z = lx.number("z coordinate");
    lx.expect(')', "to close a face point");
    return p;
}

MapFace face(Lexer& lx) {
    MapFace f;
    f.pos = lx.pos();
    for (auto& p : f.points) p = point(lx);
    // TrenchBroom quotes texture names that hold blanks or quotes.
    f.texture = lx.peek() == '"' ? lx.quoted() : lx.word("a texture name");
    if (lx.peek() == '[') {
        f.valve220 = true;
        lx.expect('[', "");
        f.uAxis = {lx.number("u axis x"), lx.number("u axis y"), lx.number("u axis z")};
        f.uOffset = lx.number("u offset");
        lx.expect(']', "to close the u axis");
        lx.expect('[', "to open the v axis");
        f.vAxis = {lx.number("v axis x"), lx.number("v axis y"), lx.number("v axis z")};
        f.vOffset = lx.number("v offset");
        lx.expect(']', "to close the v axis");
    } else {
        f.uOffset = lx.number("x offset");
        f.vOffset = lx.number("y offset");
    }
    f.rotation = lx.number("rotation");
    f.uScale = lx.number("x scale");
    f.vScale = lx.number("y scale");
    // Quake 2/3 maps add content flags, surface flags and value on the same line: keep the three
    // (as integers: flags are bit sets; a value past int's range is clamped), accept more.
    int* const flags[] = {&f.contents, &f.surfaceFlags, &f.value};
    for (int k = 0; lx.peek() != '(' && lx.peek() != '}' && lx.peek() != '\0'; ++k) {
        const double v = lx.number("surface flags");
        if (k >= 3) continue;
        f.hasFlags = true;
        *flags[k] = static_cast<int>(std::clamp(v, -2147483648.0, 2147483647.0));
    }
    return f;
}

}  // namespace

const std::string& MapEntity::value(const std::string& key) const {
    for (const auto& kv : keys)
        if (kv.first == key) return kv.second;
    return LevelEntity::empty();
}

bool MapEntity::has(const std::string& key) const {
    for (const auto& kv : keys)
        if (kv.first == key) return true;
    return false;
}

MapFile parseMap(std::string_view text, const std::string& fileName) {
    MapFile map;
    map.path = fileName;
    Lexer lx(text, fileName);
    std::size_t brushCount = 0, faceCount = 0;
    while (!lx.atEnd()) {
        if (map.entities.size() == kMaxEntitiesPerMap)
            lx.fail("more than " + std::to_string(kMaxEntitiesPerMap) + " entities in the map (the limit per level)");
        MapEntity e;
        e.pos = lx.pos();
        lx.expect('{', "to open an entity");
        for (;;) {
            const char c = lx.peek();
            if (c == '\0') lx.fail("unexpected end of file inside the entity opened at line " + std::to_string(e.pos.line));
            if (c == '}') break;
            if (c == '"') {
                if (e.keys.size() == kMaxKeysPerEntity)
                    lx.fail("entity opened at line " + std::to_string(e.pos.line) + " has more than " +
                            std::to_string(kMaxKeysPerEntity) + " keys (the limit per entity)");
                std::string key = lx.quoted();
                std::string value = lx.quoted();
                e.keys.emplace_back(std::move(key), std::move(value));
            } else if (c == '{') {
                MapBrush b;
                b.pos = lx.pos();
                lx.expect('{', "");
                if (lx.peek() != '(' && lx.peek() != '}') {
                    // patchDef2 / brushDef (Quake 3): not used by our maps; skip it whole.
                    const SourcePos at = lx.pos();
                    const std::string kind = lx.word("a block name");
                    lx.skipBlock();
                    lx.expect('}', "to close the brush");
                    map.warnings.push_back(fileName + ":" + std::to_string(at.line) + ": skipped unsupported '" + errorText(kind) + "' block");
                    continue;
                }
                while (lx.peek() == '(') {
                    if (b.faces.size() == kMaxFacesPerBrush)
                        lx.fail("brush opened at line " + std::to_string(b.pos.line) + " has more than " +
                                std::to_string(kMaxFacesPerBrush) + " faces (the limit per brush)");
                    if (++faceCount > kMaxFacesPerMap)
                        lx.fail("more than " + std::to_string(kMaxFacesPerMap) + " faces in the map (the limit per level)");
                    b.faces.push_back(face(lx));
                }
                if (lx.peek() == '\0') lx.fail("unexpected end of file inside the brush opened at line " + std::to_string(b.pos.line));
                lx.expect('}', "to close the brush (or '(' to start a face)");
                if (++brushCount > kMaxBrushesPerMap)
                    lx.fail("more than " + std::to_string(kMaxBrushesPerMap) + " brushes in the map (the limit per level)", b.pos);
                e.brushes.push_back(std::move(b));
            } else {
                lx.fail(std::string("expected '\"', '{' or '}' in an entity, found '") + errorText(std::string_view(&c, 1)) + "'");
            }
        }
        lx.expect('}', "");
        map.entities.push_back(std::move(e));
    }
    return map;
}

MapFile loadMapFile(const std::string& path) {
    std::string text, error;
    if (!readInputFile(path, kMaxMapFileBytes, "map file", text, error)) throw MapError(error);
    return parseMap(text, path);
}

}  // namespace obscura::map
