// See fgd.h.
#include "map/fgd.h"

#include "map/input_file.h"
#include "map/map_parser.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

namespace obscura::map {

// ---- writing ---------------------------------------------------------------------------------

namespace {
std::string fgdString(const std::string& s) {
    if (s.find('"') != std::string::npos) throw std::invalid_argument("FGD strings cannot hold '\"': " + s);
    return "\"" + s + "\"";
}

void writeProperty(std::ostringstream& o, const EntityKey& k) {
    o << "\t" << k.name << "(" << toString(k.type) << ")";
    if (k.type == KeyType::Flags) {
        // Flags carry no description or default of their own: each bit says whether it starts on.
        o << " =\n\t[\n";
        for (const KeyChoice& c : k.choices) o << "\t\t" << c.value << " : " << fgdString(c.label) << " : 0\n";
        o << "\t]\n";
        return;
    }
    o << " : " << fgdString(k.description);
    if (!k.defaultValue.empty()) {
        // TrenchBroom reads integer and choice defaults bare, every other default quoted.
        const bool bare = k.type == KeyType::Integer || k.type == KeyType::Choices;
        o << " : " << (bare ? k.defaultValue : fgdString(k.defaultValue));
    }
    if (k.type == KeyType::Choices) {
        o << " =\n\t[\n";
        for (const KeyChoice& c : k.choices) o << "\t\t" << c.value << " : " << fgdString(c.label) << "\n";
        o << "\t]";
    }
    o << "\n";
}

void writeClass(std::ostringstream& o, const char* kind, const std::string& attributes, const std::string& name,
                const std::string& description, const std::vector<EntityKey>& keys) {
    o << "@" << kind << attributes << " = " << name << " : " << fgdString(description) << "\n[\n";
    for (const EntityKey& k : keys) writeProperty(o, k);
    o << "]\n\n";
}
}  // namespace

std::string writeFgd(const std::vector<KeyGroup>& groups, const std::vector<EntityClass>& classes) {
    std::ostringstream o;
    o << "// Obscura's entity classes for TrenchBroom (see tools/trenchbroom/README.md).\n"
         "// Written from engine_ext/map/entity_classes.cpp by obscura_fgd; do not edit by hand:\n"
         "// change the table, then `cmake --build build --target update_fgd` (tests/map/fgd_test.cpp checks).\n\n";
    for (const KeyGroup& g : groups) writeClass(o, "BaseClass", "", g.name, g.description, g.keys);
    for (const EntityClass& c : classes) {
        std::string attributes;
        if (!c.bases.empty()) {
            attributes += " base(";
            for (std::size_t i = 0; i < c.bases.size(); ++i) attributes += (i ? ", " : "") + c.bases[i];
            attributes += ")";
        }
        if (!c.editorColour.empty()) attributes += " color(" + c.editorColour + ")";
        if (!c.editorSize.empty() && c.kind == EntityKind::Point) attributes += " size(" + c.editorSize + ")";
        writeClass(o, c.kind == EntityKind::Point ? "PointClass" : "SolidClass", attributes, c.name, c.description, c.keys);
    }
    return o.str();
}

// ---- reading ---------------------------------------------------------------------------------

namespace {
enum class Tok { End, Word, String, Punct };

struct Token {
    Tok type = Tok::End;
    std::string text;
    int line = 0;
};

class FgdReader {
public:
    FgdReader(std::string_view text, const std::string& path) : s_(text), path_(path) {}

    FgdFile read() {
        FgdFile f;
        f.path = path_;
        for (Token t = next(); t.type != Tok::End; t = next()) {
            if (t.type != Tok::Word || t.text.size() < 2 || t.text[0] != '@') fail(t.line, "expected @Class, got " + show(t));
            const std::string kind = t.text.substr(1);
            if (kind == "include" || kind == "mapsize" || kind == "MaterialExclusion" || kind == "AutoVisGroup")
                fail(t.line, "@" + kind + " is not supported here");
            f.classes.push_back(readClass(kind, t.line));
        }
        return f;
    }

private:
    [[noreturn]] void fail(int line, const std::string& problem) const {
        throw MapError(path_ + ":" + std::to_string(line) + ": " + problem);
    }
    static std::string show(const Token& t) { return t.type == Tok::End ? "end of file" : "'" + errorText(t.text) + "'"; }

    void skipSpace() {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == '\n') ++line_;
            if (std::isspace(static_cast<unsigned char>(c))) ++i_;
            else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
                while (i_ < s_.size() && s_[i_] != '\n') ++i_;
            } else break;
        }
    }

    Token lex() {
        skipSpace();
        Token t;
        t.line = line_;
        if (i_ >= s_.size()) return t;
        const char c = s_[i_];
        if (c == '"') {
            const std::size_t start = ++i_;
            while (i_ < s_.size() && s_[i_] != '"') {
                if (s_[i_] == '\n') fail(t.line, "string not closed on its line");
                ++i_;
            }
            if (i_ >= s_.size()) fail(t.line, "string not closed");
            t.type = Tok::String;
            t.text = std::string(s_.substr(start, i_ - start));
            ++i_;
            return t;
        }
        if (std::string_view("()[]:=,+").find(c) != std::string_view::npos) {
            ++i_;
            t.type = Tok::Punct;
            t.text = std::string(1, c);
            return t;
        }
        const std::size_t start = i_;
        while (i_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[i_])) &&
               std::string_view("()[]:=,+\"").find(s_[i_]) == std::string_view::npos)
            ++i_;
        t.type = Tok::Word;
        t.text = std::string(s_.substr(start, i_ - start));
        return t;
    }

    Token next() {
        if (peeked_) {
            peeked_ = false;
            return peek_;
        }
        return lex();
    }
    const Token& peek() {
        if (!peeked_) {
            peek_ = lex();
            peeked_ = true;
        }
        return peek_;
    }
    bool peekPunct(char c) { return peek().type == Tok::Punct && peek().text[0] == c; }
    Token expect(Tok type, const char* what) {
        Token t = next();
        if (t.type != type) fail(t.line, std::string("expected ") + what + ", got " + show(t));
        return t;
    }
    void expectPunct(char c) {
        Token t = next();
        if (t.type != Tok::Punct || t.text[0] != c) fail(t.line, std::string("expected '") + c + "', got " + show(t));
    }
    // A string with its "a" + "b" continuations joined.
    std::string readString() {
        std::string s = expect(Tok::String, "a quoted string").text;
        while (peekPunct('+')) {
            next();
            s += expect(Tok::String, "a quoted string after '+'").text;
        }
        return s;
    }
    // The raw text of an attribute's (...), nested parentheses and strings kept.
    std::string readAttributeText(int line) {
        skipSpace();
        if (peeked_ || i_ >= s_.size() || s_[i_] != '(') fail(line, "expected '(' after an attribute name");
        int depth = 0;
        const std::size_t start = i_ + 1;
        bool inString = false;
        for (; i_ < s_.size(); ++i_) {
            const char c = s_[i_];
            if (c == '\n') ++line_;
            if (c == '"') inString = !inString;
            else if (!inString && c == '(') ++depth;
            else if (!inString && c == ')' && --depth == 0) break;
        }
        if (i_ >= s_.size()) fail(line, "attribute's '(' not closed");
        std::string text(s_.substr(start, i_ - start));
        ++i_;
        return text;
    }

    FgdClass readClass(const std::string& kind, int line) {
        FgdClass c;
        c.kind = kind;
        c.line = line;
        while (!peekPunct('=')) {
            const Token a = expect(Tok::Word, "an attribute or '='");
            const std::string text = readAttributeText(a.line);
            const std::string name = lowerCase(a.text);
            if (name == "base") {
                std::istringstream is(text);
                for (std::string b; std::getline(is, b, ',');) {
                    b.erase(0, b.find_first_not_of(" \t\r\n"));
                    b.erase(b.find_last_not_of(" \t\r\n") + 1);
                    if (b.empty()) fail(a.line, "empty name in base(...)");
                    c.bases.push_back(b);
                }
            } else if (name == "size") c.size = text;
            else if (name == "color") c.colour = text;
            else if (name == "model" || name == "studio") c.model = text;
        }
        expectPunct('=');
        c.name = expect(Tok::Word, "a class name").text;
        if (peekPunct(':')) {
            next();
            c.description = readString();
        }
        expectPunct('[');
        while (!peekPunct(']')) c.properties.push_back(readProperty());
        expectPunct(']');
        return c;
    }

    FgdProperty readProperty() {
        FgdProperty p;
        const Token n = expect(Tok::Word, "a property name or ']'");
        p.name = n.text;
        p.line = n.line;
        expectPunct('(');
        p.type = lowerCase(expect(Tok::Word, "a property type").text);
        expectPunct(')');
        if (peek().type == Tok::Word && peek().text == "readonly") next();
        // Up to three ':'-separated fields: description, default, long description; each may be empty.
        for (int field = 0; field < 3 && peekPunct(':'); ++field) {
            next();
            if (peekPunct(':') || peekPunct('=') || peekPunct(']')) continue;
            const bool quoted = peek().type == Tok::String;
            std::string v = quoted ? readString() : expect(Tok::Word, "a value").text;
            if (field == 0) p.description = v;
            else if (field == 1) p.defaultValue = v;  // field 2, the long description, is not kept
        }
        if (p.type == "choices" || p.type == "flags") {
            expectPunct('=');
            expectPunct('[');
            int flagsOn = 0;
            while (!peekPunct(']')) {
                KeyChoice ch;
                const Token v = next();
                if (v.type != Tok::Word && v.type != Tok::String) fail(v.line, "expected a choice value, got " + show(v));
                ch.value = v.text;
                expectPunct(':');
                ch.label = readString();
                for (int field = 0; field < 2 && peekPunct(':'); ++field) {
                    next();
                    const Token x = next();
                    if (p.type == "flags" && field == 0 && x.text != "0") flagsOn |= std::atoi(ch.value.c_str());
                }
                p.choices.push_back(ch);
            }
            expectPunct(']');
            if (p.type == "flags") p.defaultValue = std::to_string(flagsOn);
        }
        return p;
    }

    static std::string lowerCase(std::string s) {
        for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        return s;
    }

    std::string_view s_;
    std::string path_;
    std::size_t i_ = 0;
    int line_ = 1;
    Token peek_;
    bool peeked_ = false;
};
}  // namespace

const FgdClass* FgdFile::find(std::string_view name) const {
    for (const FgdClass& c : classes)
        if (c.name == name) return &c;
    return nullptr;
}

std::vector<FgdProperty> FgdFile::resolvedProperties(const FgdClass& c) const {
    std::vector<FgdProperty> out;
    const auto add = [&](const FgdProperty& p) {
        if (std::none_of(out.begin(), out.end(), [&](const FgdProperty& o) { return o.name == p.name; })) out.push_back(p);
    };
    std::vector<const FgdClass*> visiting;
    const auto walk = [&](const auto& self, const FgdClass& k) -> void {
        if (std::find(visiting.begin(), visiting.end(), &k) != visiting.end())
            throw MapError(path + ":" + std::to_string(k.line) + ": " + k.name + " is its own base");
        visiting.push_back(&k);
        for (const std::string& b : k.bases) {
            const FgdClass* base = find(b);
            if (!base) throw MapError(path + ":" + std::to_string(k.line) + ": " + k.name + "'s base '" + b + "' is not defined");
            self(self, *base);
        }
        for (const FgdProperty& p : k.properties) add(p);
        visiting.pop_back();
    };
    walk(walk, c);
    return out;
}

FgdFile parseFgd(std::string_view text, const std::string& fileName) { return FgdReader(text, fileName).read(); }

FgdFile loadFgdFile(const std::string& path) {
    // An FGD is a few tens of kilobytes; 4 MiB is far above any real one (Half-Life's is ~200 kB).
    constexpr std::size_t kMaxFgdBytes = 4u << 20;
    std::string text, error;
    if (!readInputFile(path, kMaxFgdBytes, "FGD file", text, error)) throw MapError(error);
    return parseFgd(text, path);
}

// ---- comparing -------------------------------------------------------------------------------

std::vector<std::string> compareFgd(const FgdFile& fgd, const std::vector<EntityClass>& classes) {
    std::vector<std::string> out;
    const auto at = [&](int line) { return fgd.path + ":" + std::to_string(line) + ": "; };
    for (const EntityClass& rc : classes) {
        const FgdClass* fc = fgd.find(rc.name);
        const char* wantKind = rc.kind == EntityKind::Point ? "PointClass" : "SolidClass";
        if (!fc || fc->kind == "BaseClass") {
            out.push_back(fgd.path + ": class '" + rc.name + "' (" + toString(rc.kind) + ") is missing");
            continue;
        }
        if (fc->kind != wantKind) out.push_back(at(fc->line) + rc.name + " is @" + fc->kind + ", the registry has a " + toString(rc.kind) + " class");
        const std::vector<FgdProperty> props = fgd.resolvedProperties(*fc);
        const std::vector<EntityKey> keys = allKeys(rc);
        for (const EntityKey& k : keys) {
            const auto p = std::find_if(props.begin(), props.end(), [&](const FgdProperty& q) { return q.name == k.name; });
            if (p == props.end()) {
                out.push_back(at(fc->line) + rc.name + " lacks key '" + k.name + "'");
                continue;
            }
            const std::string where = at(p->line) + rc.name + " key '" + k.name + "': ";
            if (p->type != toString(k.type)) out.push_back(where + "type " + p->type + ", the registry has " + toString(k.type));
            if (p->defaultValue != k.defaultValue)
                out.push_back(where + "default '" + p->defaultValue + "', the registry has '" + k.defaultValue + "'");
            const auto sameChoice = [](const KeyChoice& a, const KeyChoice& b) { return a.value == b.value && a.label == b.label; };
            if (p->choices.size() != k.choices.size() || !std::equal(k.choices.begin(), k.choices.end(), p->choices.begin(), sameChoice))
                out.push_back(where + "its choices differ from the registry's");
        }
        for (const FgdProperty& p : props)
            if (std::none_of(keys.begin(), keys.end(), [&](const EntityKey& k) { return k.name == p.name; }))
                out.push_back(at(p.line) + rc.name + " key '" + p.name + "' is not in the registry");
    }
    for (const FgdClass& fc : fgd.classes)
        if (fc.kind != "BaseClass" && std::none_of(classes.begin(), classes.end(), [&](const EntityClass& c) { return c.name == fc.name; }))
            out.push_back(at(fc.line) + "class '" + fc.name + "' is not one the game knows (engine_ext/map/entity_classes.cpp)");
    return out;
}

}  // namespace obscura::map
