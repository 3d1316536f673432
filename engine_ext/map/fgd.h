// FGD entity definition files, as TrenchBroom reads them: writing one from the entity-class
// registry (entity_classes.h), reading one back, and comparing a file with the registry both ways.
// Plain C++ (no OGRE).
//
// The subset read is the one TrenchBroom's Quake FGDs use:
//   @BaseClass / @PointClass / @SolidClass  attributes...  = name [: "description"] [ properties ]
//   attributes: base(A, B) size(x y z, x y z) color(r g b) model(...) and any other name(...)
//   property:   name(type) [readonly] [: "description" [: default [: "long description"]]]
//               [= [ value : "label" [: default] [: "long"] ... ]]   (choices, flags)
// `//` comments, "a" + "b" string continuations. Errors: `file:line: problem` (a MapError).
#pragma once

#include "map/entity_classes.h"

#include <string>
#include <string_view>
#include <vector>

namespace obscura::map {

struct FgdProperty {
    std::string name;
    std::string type;  // as written: "string", "integer", "float", "choices", "flags", "color1"...
    std::string description;
    std::string defaultValue;  // "" when none; for flags, the sum of the bits marked on (as text)
    std::vector<KeyChoice> choices;
    int line = 0;
};

struct FgdClass {
    std::string kind;  // "BaseClass", "PointClass", "SolidClass" (as written after '@')
    std::string name;
    std::string description;
    std::vector<std::string> bases;
    std::string size, colour, model;  // the attributes' text between the parentheses, "" if absent
    std::vector<FgdProperty> properties;
    int line = 0;
};

struct FgdFile {
    std::string path;
    std::vector<FgdClass> classes;  // in file order
    const FgdClass* find(std::string_view name) const;
    // A class's properties with its bases' first (recursively; a key comes once, the first wins).
    // Throws MapError naming the line of a base that is not defined.
    std::vector<FgdProperty> resolvedProperties(const FgdClass& c) const;
};

// The registry as an FGD (the committed tools/trenchbroom/obscura/obscura.fgd is this text).
// Throws std::invalid_argument for a description holding a '"' (FGD strings cannot).
std::string writeFgd(const std::vector<KeyGroup>& groups, const std::vector<EntityClass>& classes);

FgdFile parseFgd(std::string_view text, const std::string& fileName);
FgdFile loadFgdFile(const std::string& path);  // throws MapError if unreadable or malformed

// Differences between an FGD and the registry, each a line naming the FGD's file and line where
// it has one: registry classes missing from the FGD or of the other kind, FGD classes the registry
// lacks, and per class keys missing either way or differing in type, default or choices. Empty
// when they agree. Descriptions and editor hints (size, colour) are not compared.
std::vector<std::string> compareFgd(const FgdFile& fgd, const std::vector<EntityClass>& classes);

}  // namespace obscura::map
