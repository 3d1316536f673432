// See bake_cache.h. Layout (host byte order, little-endian on every machine the game runs on; a
// file from another order reads as "not a light bake"):
//   char[8] "OBSLBAK\n"   u32 version   u64 key
//   f64 texel  i32 atlas width, height  u32 charts      (the charts themselves are rebuilt from the
//                                                         level: buildAtlas is deterministic)
//   f64 probe origin x y z, cell  i32 nx ny nz
//   f16 direct[texels * 4]  f16 indirect[texels * 3]  f16 up[probes * 3]  f16 down[probes * 3]
//   (half floats: the GPU reads them as such; e3m4's atlas is 46 MB so, 92 in floats)
//   u64 checksum of everything before it
#include "lightbake/bake_cache.h"

#include "core/half_float.h"
#include "core/state_hash.h"

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace obscura::lightbake {

namespace {
constexpr char kMagic[8] = {'O', 'B', 'S', 'L', 'B', 'A', 'K', '\n'};

void addVec(StateHasher& h, const Vec3& v) {
    h.add(v.x);
    h.add(v.y);
    h.add(v.z);
}

class Writer {
public:
    template <class T> void put(const T& v) { bytes(&v, sizeof v); }
    void bytes(const void* p, std::size_t n) {
        const auto* c = static_cast<const char*>(p);
        data.insert(data.end(), c, c + n);
    }
    void halves(const std::vector<float>& v) {
        std::vector<std::uint16_t> h(v.size());
        for (std::size_t i = 0; i < v.size(); ++i) h[i] = toHalf(v[i]);
        bytes(h.data(), h.size() * 2);
    }
    std::string data;
};

class Reader {
public:
    explicit Reader(const std::string& d) : data_(d) {}
    template <class T> bool get(T& v) { return bytes(&v, sizeof v); }
    bool bytes(void* p, std::size_t n) {
        if (data_.size() - at_ < n) return false;
        std::memcpy(p, data_.data() + at_, n);
        at_ += n;
        return true;
    }
    bool halves(std::vector<float>& v, std::size_t n) {
        if ((data_.size() - at_) / 2 < n) return false;
        v.resize(n);
        const char* p = data_.data() + at_;
        for (std::size_t i = 0; i < n; ++i) {
            std::uint16_t h;
            std::memcpy(&h, p + 2 * i, 2);
            v[i] = fromHalf(h);
        }
        at_ += 2 * n;
        return true;
    }
    std::size_t at() const { return at_; }

private:
    const std::string& data_;
    std::size_t at_ = 0;
};

// The bake as the cache stores it: a fresh bake is rounded to half floats too, so the first run of a
// level (baked) and every later one (read back) see the same light, on the GPU and in the CPU's
// lookups alike.
void roundToHalves(std::vector<float>& v) {
    for (float& x : v) x = fromHalf(toHalf(x));
}

std::uint64_t checksum(const char* p, std::size_t n) {
    StateHasher h;
    h.addBytes(p, n);
    return h.value();
}
}  // namespace

std::uint64_t bakeKey(const map::Level& level, const BakeSky& sky, const BakeSettings& settings) {
    StateHasher h;
    h.add(kBakeVersion);
    h.add(settings.texel);
    h.add(static_cast<std::int32_t>(settings.gatherRays));
    h.add(static_cast<std::int32_t>(settings.secondBounceRays));
    h.add(static_cast<std::int32_t>(settings.probeRays));
    h.add(settings.probeCell);
    h.add(settings.albedo);
    for (const Vec3& v : {sky.sunDirection, sky.sunColour, sky.above, sky.below, sky.floor}) addVec(h, v);
    for (const auto& brush : level.brushes)
        for (const auto& face : brush.faces) {
            const bool baked = bakedFace(brush, face), sky = !brush.mover && face.sky;
            h.add(baked);
            h.add(sky);
            if (!baked && !sky) continue;
            h.add(static_cast<std::uint64_t>(face.vertices.size()));
            for (const auto& v : face.vertices) addVec(h, v.position);
            addVec(h, face.normal);
        }
    for (const auto& l : level.lights) {
        addVec(h, l.position);
        addVec(h, l.colour);
        addVec(h, l.spotDirection);
        for (double d : {l.intensity, l.radius, l.unitsPerMetreScaled, l.angleScale, l.falloffExponent, l.spotCosOuter, l.spotCosInner})
            h.add(d);
        h.add(static_cast<std::int32_t>(l.formula));
        h.add(l.spot);
    }
    addVec(h, level.bounds.min);
    addVec(h, level.bounds.max);
    return h.value();
}

std::string cacheFile(const std::string& cacheDir, const std::string& levelPath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path absolute = fs::weakly_canonical(fs::path(levelPath), ec);
    if (ec) absolute = fs::absolute(fs::path(levelPath));
    StateHasher h;
    h.add(absolute.string());
    std::string name = fs::path(levelPath).filename().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
    return (fs::path(cacheDir) / "lightbake" / (name + "-" + h.hex().substr(0, 12) + ".bake")).string();
}

std::optional<LightBake> loadBake(const std::string& file, const map::Level& level, std::uint64_t key, std::string& why) {
    why.clear();
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Reader r(data);
    char magic[8];
    std::uint32_t version = 0;
    std::uint64_t stored = 0;
    if (!r.bytes(magic, 8) || std::memcmp(magic, kMagic, 8) != 0) {
        why = "not a light bake";
        return std::nullopt;
    }
    if (!r.get(version) || !r.get(stored)) {
        why = "truncated";
        return std::nullopt;
    }
    if (version != kBakeVersion || stored != key) {
        why = version != kBakeVersion ? "stale (an older bake)" : "stale (the level or the bake's settings changed)";
        return std::nullopt;
    }
    if (data.size() < r.at() + sizeof(std::uint64_t)) {
        why = "truncated";
        return std::nullopt;
    }
    std::uint64_t sum = 0;
    std::memcpy(&sum, data.data() + data.size() - sizeof sum, sizeof sum);
    if (sum != checksum(data.data(), data.size() - sizeof sum)) {
        why = "corrupt or truncated (its checksum does not match)";
        return std::nullopt;
    }
    LightBake bake;
    double texel = 0;
    std::int32_t w = 0, hgt = 0, nx = 0, ny = 0, nz = 0;
    std::uint32_t charts = 0;
    ProbeGrid& g = bake.probes;
    bool ok = r.get(texel) && r.get(w) && r.get(hgt) && r.get(charts) && r.get(g.origin.x) && r.get(g.origin.y) &&
              r.get(g.origin.z) && r.get(g.cell) && r.get(nx) && r.get(ny) && r.get(nz);
    if (ok) {
        bake.atlas = buildAtlas(level, texel);
        ok = bake.atlas.width == w && bake.atlas.height == hgt && bake.atlas.charts.size() == charts && nx >= 0 && ny >= 0 && nz >= 0;
    }
    if (ok) {
        g.nx = nx;
        g.ny = ny;
        g.nz = nz;
        ok = r.halves(bake.direct, bake.atlas.texels() * 4) && r.halves(bake.indirect, bake.atlas.texels() * 3) &&
             r.halves(g.up, g.count() * 3) && r.halves(g.down, g.count() * 3) && r.at() + sizeof sum == data.size();
    }
    if (!ok) {
        why = "corrupt (its sizes do not match the level)";
        return std::nullopt;
    }
    bake.stats.charts = charts;
    bake.stats.texels = bake.atlas.texels();
    bake.stats.probes = g.count();
    bake.stats.lights = level.lights.size();
    return bake;
}

void saveBake(const std::string& file, std::uint64_t key, const LightBake& bake) {
    namespace fs = std::filesystem;
    Writer w;
    w.bytes(kMagic, 8);
    w.put(kBakeVersion);
    w.put(key);
    w.put(bake.atlas.texel);
    w.put(static_cast<std::int32_t>(bake.atlas.width));
    w.put(static_cast<std::int32_t>(bake.atlas.height));
    w.put(static_cast<std::uint32_t>(bake.atlas.charts.size()));
    const ProbeGrid& g = bake.probes;
    for (double d : {g.origin.x, g.origin.y, g.origin.z, g.cell}) w.put(d);
    for (int n : {g.nx, g.ny, g.nz}) w.put(static_cast<std::int32_t>(n));
    w.halves(bake.direct);
    w.halves(bake.indirect);
    w.halves(g.up);
    w.halves(g.down);
    w.put(checksum(w.data.data(), w.data.size()));

    std::error_code ec;
    fs::create_directories(fs::path(file).parent_path(), ec);
    // A temporary of this process's own: two games loading one level at once (a test suite run
    // in parallel) each write theirs, and the last rename wins with a whole file.
    const std::string temp = file + "." + std::to_string(::getpid()) + ".part";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(w.data.data(), static_cast<std::streamsize>(w.data.size()));
        if (!out) throw std::runtime_error(temp + ": cannot write the light bake");
    }
    fs::rename(temp, file, ec);
    if (ec) throw std::runtime_error(file + ": cannot store the light bake (" + ec.message() + ")");
}

BakeOutcome bakeOrLoad(const map::Level& level, const BakeSky& sky, const BakeSettings& settings, const std::string& cacheDir,
                       const std::function<void(const std::string&)>& log) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    BakeOutcome out;
    out.file = cacheFile(cacheDir, level.sourcePath);
    const std::uint64_t key = bakeKey(level, sky, settings);
    std::string why;
    if (auto cached = loadBake(out.file, level, key, why)) {
        out.bake = std::move(*cached);
        out.fromCache = true;
        out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return out;
    }
    if (!why.empty() && log) log("lightbake: " + out.file + ": " + why + "; baking again");
    out.bake = bakeLevel(level, sky, settings, log);
    for (auto* v : {&out.bake.direct, &out.bake.indirect, &out.bake.probes.up, &out.bake.probes.down}) roundToHalves(*v);
    try {
        saveBake(out.file, key, out.bake);
    } catch (const std::exception& e) {
        if (log) log(std::string("lightbake: ") + e.what() + "; the bake is used without being stored");
    }
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
}

}  // namespace obscura::lightbake
