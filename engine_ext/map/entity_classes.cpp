// See entity_classes.h. Defaults are the ones the reading code applies (its file named beside each
// class); a change there must change the value here (tests/map/fgd_test.cpp checks the FGD, not the
// reading code, so the names of the files are the link).
#include "map/entity_classes.h"

#include <algorithm>

namespace obscura::map {

namespace {
using T = KeyType;
using R = EntityRole;

EntityKey key(std::string name, KeyType type, std::string def, std::string description, std::vector<KeyChoice> choices = {}) {
    return {std::move(name), type, std::move(def), std::move(description), std::move(choices)};
}
EntityKey sounds(std::string def, std::vector<KeyChoice> choices) {
    return key("sounds", T::Choices, std::move(def), "Sound set (Quake's; Obscura plays none of them yet)", std::move(choices));
}

std::vector<KeyGroup> makeGroups() {
    return {
        {"Targetname", "Can be named, for other entities to refer to", {key("targetname", T::TargetSource, "", "Name")}},
        {"Target",
         "Refers to other entities by name",
         {key("target", T::TargetDestination, "", "Entity to trigger or to move to"),
          key("killtarget", T::TargetDestination, "", "Entity to remove when fired")}},
        {"Yaw",
         "Faces a direction (map_compile.cpp: 'angles' wins over 'angle')",
         {key("angle", T::Float, "0", "Yaw in degrees, counter-clockwise from east (-1 up, -2 down count as 0)"),
          key("angles", T::String, "", "'pitch yaw roll' in degrees; only the yaw is used")}},
        {"MoveDirection",
         "Moves along a direction (game/sim/movers.h)",
         {key("angle", T::Float, "0", "Direction to move, degrees (-1 up, -2 down)")}},
        // map_compile.cpp addLight: every Quake light class becomes one point light.
        {"Light",
         "A point light",
         {key("light", T::Integer, "300", "Brightness; also the radius of influence in map units"),
          key("_light", T::Integer, "300", "Brightness when 'light' is absent (some tools write this)"),
          key("_color", T::Colour, "1 1 1", "Colour, 0..1 or 0..255"), key("color", T::Colour, "1 1 1", "Colour when '_color' is absent"),
          key("_sun", T::Integer, "0", "1: this light is the level's sun, along its mangle (unless worldspawn sets _sunlight)"),
          key("_nostaticlight", T::Integer, "0", "1: lights nothing (ericw-tools: dynamic only)"),
          key("targetname", T::TargetSource, "", "Name (with spawnflags 1, START_OFF: dark until triggered)"),
          key("target", T::TargetDestination, "", "An entity to aim at: a spotlight"),
          key("mangle", T::String, "", "'yaw pitch roll' in degrees: a spotlight along it (when no target)"),
          key("_cone", T::Float, "40", "Spotlight cone, degrees across (also 'angle' on a spotlight)"),
          key("_softangle", T::Float, "0", "Spotlight inner cone at full light, degrees (0: none)"),
          key("delay", T::Integer, "0", "Falloff: 0 linear, 1 1/d, 2 1/d^2, 3 none, 4 local minimum, 5 1/(d+128)^2"),
          key("wait", T::Float, "1", "Distance scale of the falloff (ericw-tools)"),
          key("_falloff", T::Float, "0", "Linear lights: the distance in map units where the light reaches 0 (0: from 'light')"),
          key("_falloff_exponent", T::Float, "1", "Obscura: linear falloff's exponent (1 Quake's, 2 smoother)"),
          key("_anglescale", T::Float, "0.5", "How much the angle of incidence dims the light (0 none, 1 Lambert; also _anglesense)"),
          key("_anglesense", T::Float, "0.5", "The older name of _anglescale"),
          key("spawnflags", T::Flags, "0", "", {{"1", "Start off (with a targetname)"}})}},
        // game/sim/combat.cpp Combat::Combat.
        {"Board",
         "A shooting-range board standing on its origin, facing its yaw",
         {key("width", T::Float, "0.6", "Board width, metres (0.05 to 10)"),
          key("height", T::Float, "1.6", "Board height, metres (0.05 to 10)"),
          key("reset", T::Float, "3", "Seconds down after a hit before it rises (up to 600)")}},
        {"Trigger",
         "Fires its target when the player enters it (an invisible, non-solid volume; game/sim/triggers.h)",
         {key("delay", T::Float, "0", "Seconds before firing"), key("message", T::String, "", "Text shown when fired"),
          key("health", T::Integer, "0", "If set, must be shot instead of touched"),
          key("spawnflags", T::Flags, "0", "", {{"1", "Not touchable"}})}},
    };
}

std::vector<EntityClass> makeClasses() {
    const std::vector<KeyChoice> doorSounds = {{"0", "None"}, {"1", "Stone"}, {"2", "Machine"}, {"3", "Stone chain"}, {"4", "Screechy metal"}};
    std::vector<EntityClass> c;
    // Editor boxes of the game's props and boards: their default size at Quake's 32 units a metre
    // (a 0.75 m crate is 24 units); the Quake classes keep Quake's boxes.
    // Read by map_compile.cpp (units_per_metre) and render/level_lighting.cpp (the sun and sky dome).
    c.push_back({"worldspawn", EntityKind::Brush, R::World, BrushRole::Solid, "The level: its static brushes and level-wide settings",
                 {},
                 {key("units_per_metre", T::Float, "32", "Map units per metre (1 to 1024; --map-scale overrides)"),
                  key("_sunlight", T::Float, "0", "Sun brightness (200 gives a sun of colour 1; 0 is no sun)"),
                  key("_sun_mangle", T::String, "0 -90 0", "Sun direction, 'yaw pitch roll' in degrees (the default points straight down)"),
                  key("_sunlight_color", T::Colour, "1 1 1", "Sun colour, 0..255 or 0..1"),
                  key("_sunlight2", T::Float, "0", "Sky-dome fill light brightness (0 is none)"),
                  key("_sunlight2_color", T::Colour, "1 1 1", "Sky-dome colour, 0..255 or 0..1"),
                  key("_sunlight_mangle", T::String, "", "Sun direction, as _sun_mangle (ericw-tools' other name)"),
                  key("_sun_angle", T::String, "", "Sun direction, as _sun_mangle (another tool's name)"),
                  key("_sunlight_color2", T::Colour, "", "Sky-dome colour, as _sunlight2_color"),
                  key("_sunlight3", T::Float, "0", "Lower-dome fill light brightness (light from below; 0 is none)"),
                  key("_sunlight3_color", T::Colour, "1 1 1", "Lower-dome colour (also _sunlight_color3)"),
                  key("_sunlight_color3", T::Colour, "", "Lower-dome colour, as _sunlight3_color"),
                  key("_minlight", T::Float, "0", "Light every surface gets at least (Quake units, 0..255)"),
                  key("_minlight_color", T::Colour, "1 1 1", "Colour of _minlight (also _mincolor)"),
                  key("_mincolor", T::Colour, "", "Colour of _minlight, as _minlight_color"),
                  key("_dist", T::Float, "1", "Scale of every light's falloff distance (ericw-tools)"),
                  key("worldtype", T::Integer, "0", "What keys are called in messages: 0 key, 1 runekey, 2 keycard"),
                  key("_ambient_sky", T::Colour, "", "Obscura: the ambient from above, linear RGB 0..1 (replaces _minlight's)"),
                  key("_ambient_ground", T::Colour, "", "Obscura: the ambient from below, linear RGB 0..1"),
                  key("_wateralpha", T::Float, "1", "Opacity of water (0..1; also 'wateralpha'): below 1 translucent"),
                  key("_slimealpha", T::Float, "1", "Opacity of slime (0..1; also 'slimealpha'; unset: the water's)"),
                  key("_lavaalpha", T::Float, "1", "Opacity of lava (0..1; also 'lavaalpha'; unset: the water's)"),
                  key("_telealpha", T::Float, "1", "Opacity of teleporter liquid (0..1; also 'telealpha'; unset: the water's)")},
                 "", ""});
    // Player starts (map_compile.cpp): an unnamed info_player_start beats a named one (Quake 2's
    // level-transition starts), which beats deathmatch, which beats coop; the first of each wins.
    const char* startSize = "-16 -16 -24, 16 16 32";  // Quake's player hull about the origin
    c.push_back({"info_player_start", EntityKind::Point, R::PlayerStart, BrushRole::Solid,
                 "Where the player spawns (feet 24 units below the origin). One with a targetname is a named start "
                 "(Quake 2's level transitions) and loses to one without",
                 {"Targetname", "Yaw"}, {}, "0 255 0", startSize});
    c.push_back({"info_player_deathmatch", EntityKind::Point, R::PlayerStart, BrushRole::Solid,
                 "Spawn point used when the level has no info_player_start", {"Yaw"}, {}, "255 0 255", startSize});
    c.push_back({"info_player_coop", EntityKind::Point, R::PlayerStart, BrushRole::Solid,
                 "Spawn point used when the level has neither info_player_start nor info_player_deathmatch", {"Yaw"}, {},
                 "0 128 255", startSize});
    // Lights: Quake's light classes, all one point light (the Light base).
    const char* lights[][2] = {{"light", "A point light"},
                               {"light_fluoro", "A point light (Quake's humming fluorescent; no sound here)"},
                               {"light_fluorospark", "A point light (Quake's sparking fluorescent; no sound here)"},
                               {"light_globe", "A point light (Quake's globe sprite is not drawn)"},
                               {"light_flame_large_yellow", "A point light (Quake's large flame; the flame is not drawn)"},
                               {"light_flame_small_yellow", "A point light (Quake's small flame; the flame is not drawn)"},
                               {"light_flame_small_white", "A point light (Quake's small white flame; the flame is not drawn)"},
                               {"light_torch_small_walltorch", "A point light (Quake's wall torch; the torch is not drawn)"}};
    for (const auto& [name, what] : lights)
        c.push_back({name, EntityKind::Point, R::Light, BrushRole::Solid, what, {"Light"}, {}, "255 255 64", "-8 -8 -8, 8 8 8"});
    // map_compile.cpp addModel; render/model_loader.cpp places it, session.cpp collides with it.
    c.push_back({"misc_model", EntityKind::Point, R::Model, BrushRole::Solid,
                 "A static OGRE .mesh with a triangle collider (the file beside the level, or in media/)",
                 {"Yaw"},
                 {key("model", T::String, "", "Mesh file or resource name (up to 255 characters)"),
                  key("scale", T::Float, "1", "Uniform scale, 0.001 to 1000"),
                  key("modelscale", T::Float, "1", "Scale when 'scale' is absent")},
                 "255 128 0", ""});
    // game/sim/physics_world.cpp addLevel.
    // Quake's keys (game/sim/pickups.h): taken by touch, used up by the func_door that needs one.
    c.push_back({"item_key1", EntityKind::Point, R::Game, BrushRole::Solid,
                 "The silver key: taken by touch; opens a func_door with spawnflags 16 (not drawn yet)", {}, {}, "0 128 255",
                 "-16 -16 -24, 16 16 32"});
    c.push_back({"item_key2", EntityKind::Point, R::Game, BrushRole::Solid,
                 "The gold key: taken by touch; opens a func_door with spawnflags 8 (not drawn yet)", {}, {}, "255 200 0",
                 "-16 -16 -24, 16 16 32"});
    c.push_back({"prop_crate", EntityKind::Point, R::Game, BrushRole::Solid,
                 "A wooden crate: a Bullet box the player pushes and shots knock about (origin at its bottom centre)",
                 {"Yaw"},
                 {key("size", T::Float, "0.75", "Edge length, metres (0.05 to 10)"), key("mass", T::Float, "20", "Mass, kg (up to 10000)")},
                 "160 110 50", "-12 -12 0, 12 12 24"});
    c.push_back({"prop_barrel", EntityKind::Point, R::Game, BrushRole::Solid,
                 "An oil drum: a Bullet cylinder standing on its origin, pushed and tipped like a crate",
                 {"Yaw"},
                 {key("radius", T::Float, "0.3", "Radius, metres (0.05 to 10)"), key("height", T::Float, "0.9", "Height, metres (0.05 to 10)"),
                  key("mass", T::Float, "12", "Mass, kg (up to 10000)")},
                 "90 120 160", "-10 -10 0, 10 10 29"});
    // Targets (the Board base; game/sim/combat.cpp).
    c.push_back({"target_popup", EntityKind::Point, R::Game, BrushRole::Solid, "A board that falls when hit and rises after 'reset'",
                 {"Yaw", "Board"}, {}, "255 64 64", "-10 -2 0, 10 2 51"});
    c.push_back({"target_moving", EntityKind::Point, R::Game, BrushRole::Solid, "A target_popup that slides back and forth across the range",
                 {"Yaw", "Board"},
                 {key("speed", T::Float, "2", "Sliding speed, metres a second (up to 50)"),
                  key("distance", T::Float, "6", "Slide length to its left and back, metres (up to 200)")},
                 "255 128 64", "-10 -2 0, 10 2 51"});
    // engine_ext/decals/decal_sign.cpp readSign.
    c.push_back({"decal_sign", EntityKind::Point, R::Game, BrushRole::Solid,
                 "Text or an image painted as a decal on the surface the origin sits on (exactly one of 'text', 'image')",
                 {},
                 {key("text", T::String, "", "Text to paint (up to 32 characters)"),
                  key("image", T::String, "", "PNG file beside the level or in media/ instead of text"),
                  key("angle", T::Float, "0", "Facing yaw, degrees (the decal projects against it)"),
                  key("mangle", T::String, "", "'pitch yaw roll' in degrees; wins over 'angle'"),
                  key("size", T::Float, "1", "Width and height, metres (up to 16)"),
                  key("depth", T::Float, "0.2", "Projection depth, metres (up to 4)"),
                  key("_color", T::Colour, "0.92 0.9 0.85", "Tint, 0..1 or 0..255"),
                  key("style", T::String, "smooth", "Words among alpha, smooth, outline, glow, shadow")},
                 "255 255 255", "-4 -4 -4, 4 4 4"});
    // engine_ext/signs/sign_light.cpp readSign (the SignSpec defaults in sign_light.h).
    c.push_back({"light_sign", EntityKind::Point, R::Game, BrushRole::Solid,
                 "A back-lit text sign: an opaque plate centred at the origin, lit only through its letters by a lamp "
                 "behind it (light shafts in smoke, lettered light on what it faces)",
                 {},
                 {key("text", T::String, "", "Text of the letters (1 to 48 characters)"),
                  key("font", T::String, "DejaVuSans-Bold.ttf", "Font file name, looked up in the font folder"),
                  key("angle", T::Float, "0", "Yaw the sign faces, degrees (its light travels that way)"),
                  key("mangle", T::String, "", "'pitch yaw roll' in degrees (pitch down positive); wins over 'angle'"),
                  key("size", T::Float, "0.4", "Letter height (the font's em), metres (up to 4)"),
                  key("margin", T::Float, "0.1", "Plate around the text on every side, metres (0 to 4)"),
                  key("_color", T::Colour, "1 0.85 0.6", "Light colour, 0..1 or 0..255"),
                  key("light", T::Float, "6", "Intensity: irradiance at 1 m straight through a letter (0 to 1000)"),
                  key("plate_color", T::Colour, "0.05 0.05 0.06", "Colour of the plate's front, 0..1 or 0..255"),
                  key("light_distance", T::Float, "0.3", "Lamp distance behind the plate's centre, metres (up to 8)"),
                  key("light_origin", T::String, "", "Lamp position 'x y z' in map units, behind the plate; wins over 'light_distance'"),
                  key("light_radius", T::Float, "0.03", "Lamp sphere radius, metres (up to 1): the penumbra's width"),
                  key("cone", T::Float, "75", "Half angle of the lamp's cone about the facing, degrees (1 to 90)"),
                  key("range", T::Float, "12", "Metres from the lamp where the light has faded out (up to 64)")},
                 "255 200 120", "-4 -4 -4, 4 4 4"});
    c.push_back({"info_sign", EntityKind::Point, R::Marker, BrushRole::Solid,
                 "Marks the arena's sign wall for tools/levelgen's self-check; the game draws nothing for it (decal_sign "
                 "paints signs)",
                 {},
                 {key("angle", T::Float, "0", "Which way the sign faces, degrees"), key("text", T::String, "", "Sign text"),
                  key("width", T::Float, "", "Width, metres"), key("height", T::Float, "", "Height, metres")},
                 "200 200 200", ""});
    // Markers: named points movers and teleporters refer to.
    c.push_back({"info_null", EntityKind::Point, R::Marker, BrushRole::Solid, "A named point (Quake removes it at spawn)",
                 {"Targetname"}, {}, "", "-4 -4 -4, 4 4 4"});
    c.push_back({"info_notnull", EntityKind::Point, R::Marker, BrushRole::Solid, "A named point that stays", {"Targetname"}, {}, "",
                 "-4 -4 -4, 4 4 4"});
    c.push_back({"info_teleport_destination", EntityKind::Point, R::Marker, BrushRole::Solid,
                 "Where a trigger_teleport sends the player, facing its angle", {"Targetname", "Yaw"}, {},
                 "128 128 255", startSize});
    c.push_back({"path_corner", EntityKind::Point, R::Marker, BrushRole::Solid,
                 "A corner of a func_train's path (trains do not move yet)", {"Targetname"},
                 {key("target", T::TargetDestination, "", "Next path_corner"), key("wait", T::Float, "0", "Seconds the train waits here")},
                 "128 76 0", "-8 -8 -8, 8 8 8"});
    // Brush groups compiled with the world.
    const char* solidGroups[][2] = {{"func_group", "Brushes grouped in the editor; compiled as world"},
                                    {"func_detail", "Detail brushes; compiled as world"},
                                    {"func_detail_wall", "Detail brushes; compiled as world"},
                                    {"func_detail_fence", "Detail brushes (fences); compiled as world"},
                                    {"func_wall", "A wall entity; compiled with the world"}};
    for (const auto& [name, what] : solidGroups)
        c.push_back({name, EntityKind::Brush, R::Geometry, BrushRole::Solid, what, {}, {}, "", ""});
    c.push_back({"func_illusionary", EntityKind::Brush, R::Geometry, BrushRole::NonSolid, "Rendered but not solid", {}, {}, "", ""});
    c.push_back({"func_detail_illusionary", EntityKind::Brush, R::Geometry, BrushRole::NonSolid, "Detail brushes, rendered but not solid",
                 {}, {}, "", ""});
    // Quake movers (game/sim/movers.h; the keys are Quake's).
    c.push_back({"func_door", EntityKind::Brush, R::Mover, BrushRole::Solid, "A door",
                 {"Targetname", "Target", "MoveDirection"},
                 {key("speed", T::Float, "100", "Units a second"), key("wait", T::Float, "3", "Seconds open before closing (-1 stays open)"),
                  key("lip", T::Float, "8", "Units left showing when open"), key("dmg", T::Integer, "2", "Damage when blocked"),
                  key("health", T::Integer, "0", "If set, must be shot open"), key("message", T::String, "", "Text when touched"),
                  sounds("0", doorSounds),
                  key("spawnflags", T::Flags, "0", "",
                      {{"1", "Starts open"}, {"4", "Don't link"}, {"8", "Gold key"}, {"16", "Silver key"}, {"32", "Toggle"}})},
                 "", ""});
    c.push_back({"func_door_secret", EntityKind::Brush, R::Mover, BrushRole::Solid,
                 "A secret door that slides back then sideways", {"Targetname", "MoveDirection"},
                 {key("wait", T::Float, "5", "Seconds open before closing"), key("t_width", T::Float, "", "Sideways distance (default: its width)"),
                  key("t_length", T::Float, "", "Back distance (default: its depth)"), key("dmg", T::Integer, "2", "Damage when blocked"),
                  key("message", T::String, "", "Text when touched"), sounds("3", {{"1", "Medieval"}, {"2", "Metal"}, {"3", "Base"}}),
                  key("spawnflags", T::Flags, "0", "",
                      {{"1", "Open once"}, {"2", "First left"}, {"4", "First down"}, {"8", "No shoot"}, {"16", "Always shoot"}})},
                 "", ""});
    c.push_back({"func_plat", EntityKind::Brush, R::Mover, BrushRole::Solid, "A lift",
                 {"Targetname"},
                 {key("speed", T::Float, "150", "Units a second"), key("height", T::Float, "", "Travel (default: its height minus 8)"),
                  sounds("1", {{"1", "Base fast"}, {"2", "Chain slow"}}), key("spawnflags", T::Flags, "0", "", {{"1", "Low trigger"}})},
                 "", ""});
    c.push_back({"func_button", EntityKind::Brush, R::Mover, BrushRole::Solid,
                 "A button that fires its target", {"Targetname", "Target", "MoveDirection"},
                 {key("speed", T::Float, "40", "Units a second"), key("wait", T::Float, "1", "Seconds before it returns (-1 stays in)"),
                  key("lip", T::Float, "4", "Units left showing when pressed"), key("health", T::Integer, "0", "If set, must be shot"),
                  key("delay", T::Float, "0", "Seconds before firing"), key("message", T::String, "", "Text when pressed"),
                  sounds("0", {{"0", "Steam metal"}, {"1", "Wooden clunk"}, {"2", "Metallic click"}, {"3", "In-out"}})},
                 "", ""});
    c.push_back({"func_train", EntityKind::Brush, R::Mover, BrushRole::Solid,
                 "A platform moving along path_corners", {"Targetname"},
                 {key("target", T::TargetDestination, "", "First path_corner"), key("speed", T::Float, "100", "Units a second"),
                  key("dmg", T::Integer, "2", "Damage when blocked"), sounds("0", {{"0", "None"}, {"1", "Ratchet metal"}})},
                 "", ""});
    // Obscura's lighting volumes (map/map_lights.h: Level::ambientAreas).
    c.push_back({"env_ambient", EntityKind::Brush, R::Game, BrushRole::Volume,
                 "Scales the level's ambient light inside its brushes' box (an enclosed room the sky does not reach); "
                 "invisible and not solid. Draw it over the room's inner faces",
                 {},
                 {key("ambient", T::Float, "0.1", "The level's ambient light times this inside the box (0 to 1)"),
                  key("blend", T::Float, "0", "Metres over which it fades across the box's faces, centred on them (0 = a hard edge; up to 4)")},
                 "", ""});
    // Triggers: invisible, non-solid volumes the player fires (game/sim/triggers.h).
    c.push_back({"trigger_multiple", EntityKind::Brush, R::Trigger, BrushRole::Volume, "Fires its target each time it is entered",
                 {"Targetname", "Target", "Trigger"}, {key("wait", T::Float, "0.2", "Seconds before it can fire again")}, "", ""});
    c.push_back({"trigger_once", EntityKind::Brush, R::Trigger, BrushRole::Volume, "Fires its target once",
                 {"Targetname", "Target", "Trigger"}, {}, "", ""});
    c.push_back({"trigger_secret", EntityKind::Brush, R::Trigger, BrushRole::Volume, "Fires its target once and counts a secret",
                 {"Targetname", "Target", "Trigger"}, {}, "", ""});
    c.push_back({"trigger_relay", EntityKind::Point, R::Trigger, BrushRole::Solid, "Fires its targets when it is fired (after its delay)",
                 {"Targetname", "Target"}, {key("delay", T::Float, "0", "Seconds before firing")},
                 "128 128 128", "-8 -8 -8, 8 8 8"});
    c.push_back({"trigger_counter", EntityKind::Point, R::Trigger, BrushRole::Solid, "Fires its target after it has been fired 'count' times",
                 {"Targetname", "Target"}, {key("count", T::Integer, "2", "Firings needed")}, "128 128 128", "-8 -8 -8, 8 8 8"});
    c.push_back({"trigger_teleport", EntityKind::Brush, R::Trigger, BrushRole::Volume,
                 "Sends the player to the info_teleport_destination named by its target", {"Targetname"},
                 {key("target", T::TargetDestination, "", "The info_teleport_destination"),
                  key("spawnflags", T::Flags, "0", "", {{"1", "Player only"}, {"2", "Silent"}})},
                 "", ""});
    c.push_back({"trigger_hurt", EntityKind::Brush, R::Trigger, BrushRole::Volume, "Hurts the player inside it, at most once a second",
                 {"Targetname"}, {key("dmg", T::Integer, "5", "Health taken a touch")}, "", ""});
    c.push_back({"trigger_changelevel", EntityKind::Brush, R::Trigger, BrushRole::Volume,
                 "Ends the level: the game loads 'map' from beside this one (a replay ends here)", {"Target"},
                 {key("map", T::String, "", "The next level's name: <map>.map in this level's folder")}, "", ""});
    c.push_back({"trigger_push", EntityKind::Brush, R::Trigger, BrushRole::Volume, "Pushes what enters it along its angle",
                 {"Targetname", "MoveDirection"},
                 {key("speed", T::Float, "1000", "Push speed, units a second"), key("spawnflags", T::Flags, "0", "", {{"1", "Push once"}})}, "",
                 ""});
    return c;
}
}  // namespace

const std::vector<KeyGroup>& keyGroups() {
    static const std::vector<KeyGroup> groups = makeGroups();
    return groups;
}

const std::vector<EntityClass>& entityClasses() {
    static const std::vector<EntityClass> classes = makeClasses();
    return classes;
}

const KeyGroup* findKeyGroup(std::string_view name) {
    for (const KeyGroup& g : keyGroups())
        if (g.name == name) return &g;
    return nullptr;
}

const EntityClass* findEntityClass(std::string_view classname) {
    for (const EntityClass& c : entityClasses())
        if (c.name == classname) return &c;
    return nullptr;
}

bool isKnownClass(std::string_view classname) { return findEntityClass(classname) != nullptr; }

std::vector<EntityKey> allKeys(const EntityClass& c) {
    std::vector<EntityKey> keys;
    const auto add = [&](const EntityKey& k) {
        if (std::none_of(keys.begin(), keys.end(), [&](const EntityKey& o) { return o.name == k.name; })) keys.push_back(k);
    };
    for (const std::string& b : c.bases)
        if (const KeyGroup* g = findKeyGroup(b))
            for (const EntityKey& k : g->keys) add(k);
    for (const EntityKey& k : c.keys) add(k);
    return keys;
}

const char* toString(EntityKind k) { return k == EntityKind::Point ? "point" : "brush"; }

const char* toString(KeyType t) {
    switch (t) {
        case KeyType::String: return "string";
        case KeyType::Integer: return "integer";
        case KeyType::Float: return "float";
        case KeyType::Colour: return "color1";
        case KeyType::Choices: return "choices";
        case KeyType::Flags: return "flags";
        case KeyType::TargetSource: return "target_source";
        case KeyType::TargetDestination: return "target_destination";
    }
    return "string";
}

}  // namespace obscura::map
