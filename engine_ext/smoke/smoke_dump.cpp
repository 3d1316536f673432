// See smoke_dump.h.
#include "smoke/smoke_dump.h"

#include "core/byte_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>

namespace obscura::smoke {

namespace {
constexpr long kMaxCells = 1L << 26;  // 64 M cells a volume: far beyond any grid the game makes

struct Reader {
    std::istream& in;
    const std::string& name;
    int line = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw DumpError(name + ":" + std::to_string(line) + ": " + what);
    }
    std::string next(const char* expected) {
        std::string s;
        if (!std::getline(in, s)) fail(std::string("the file ends where ") + expected + " was expected");
        ++line;
        if (!s.empty() && s.back() == '\r') s.pop_back();
        return s;
    }
};

template <class T>
bool readWord(std::istringstream& is, const char* word, T& value) {
    std::string w;
    return (is >> w) && w == word && (is >> value);
}
bool atEnd(std::istringstream& is) {
    std::string rest;
    return !(is >> rest);
}
}  // namespace

double DumpVolume::densityAt(const Vec3& p) const {
    if (nx <= 0 || ny <= 0 || nz <= 0 || !(cellSize > 0)) return 0;
    const double u = (p.x - origin.x) / cellSize, v = (p.y - origin.y) / cellSize, w = (p.z - origin.z) / cellSize;
    if (u < 0 || v < 0 || w < 0 || u > nx || v > ny || w > nz) return 0;
    // cell centres at i + 0.5: clamp to them (a texture's clamp-to-edge)
    auto axis = [](double c, int n, int& i0, int& i1, double& f) {
        c = std::clamp(c - 0.5, 0.0, n - 1.0);
        i0 = std::min(static_cast<int>(c), n - 1);
        i1 = std::min(i0 + 1, n - 1);
        f = c - i0;
    };
    int x0, x1, y0, y1, z0, z1;
    double fx, fy, fz;
    axis(u, nx, x0, x1, fx);
    axis(v, ny, y0, y1, fy);
    axis(w, nz, z0, z1, fz);
    auto d = [&](int i, int j, int k) {
        return static_cast<double>(density[(static_cast<std::size_t>(k) * ny + j) * nx + i]);
    };
    auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
    return lerp(lerp(lerp(d(x0, y0, z0), d(x1, y0, z0), fx), lerp(d(x0, y1, z0), d(x1, y1, z0), fx), fy),
                lerp(lerp(d(x0, y0, z1), d(x1, y0, z1), fx), lerp(d(x0, y1, z1), d(x1, y1, z1), fx), fy), fz);
}

SmokeDump readSmokeDump(std::istream& in, const std::string& name) {
    Reader r{in, name};
    SmokeDump dump;
    if (r.next("the header 'obscura-smoke-dump 1'") != "obscura-smoke-dump 1")
        r.fail("not a smoke dump (the first line must be 'obscura-smoke-dump 1')");
    {
        std::istringstream is(r.next("'time <s> sigma <per metre>'"));
        if (!readWord(is, "time", dump.time) || !readWord(is, "sigma", dump.sigma) || !atEnd(is))
            r.fail("expected 'time <seconds> sigma <per metre>'");
        if (!std::isfinite(dump.time) || !std::isfinite(dump.sigma) || dump.sigma < 0)
            r.fail("time must be finite and sigma finite and not negative");
    }
    long count = 0;
    {
        std::istringstream is(r.next("'volumes <N>'"));
        if (!readWord(is, "volumes", count) || !atEnd(is) || count < 0 || count > 1024)
            r.fail("expected 'volumes <N>' with 0 <= N <= 1024");
    }
    const bool swap = !hostLittleEndian();
    for (long v = 0; v < count; ++v) {
        const std::string what = "volume " + std::to_string(v + 1) + " of " + std::to_string(count);
        std::istringstream is(r.next(("'volume nx ny nz ox oy oz cell' (" + what + ")").c_str()));
        DumpVolume vol;
        long n[3];
        if (!readWord(is, "volume", n[0]) || !(is >> n[1] >> n[2] >> vol.origin.x >> vol.origin.y >> vol.origin.z >> vol.cellSize) ||
            !atEnd(is))
            r.fail(what + ": expected 'volume <nx> <ny> <nz> <origin x> <origin y> <origin z> <cellSize>'");
        if (n[0] <= 0 || n[1] <= 0 || n[2] <= 0 || n[0] * n[1] > kMaxCells || n[0] * n[1] * n[2] > kMaxCells)
            r.fail(what + ": bad grid size " + std::to_string(n[0]) + "x" + std::to_string(n[1]) + "x" + std::to_string(n[2]));
        if (!(vol.cellSize > 0) || !std::isfinite(vol.cellSize) || !std::isfinite(vol.origin.x + vol.origin.y + vol.origin.z))
            r.fail(what + ": the origin must be finite and the cell size positive");
        vol.nx = static_cast<int>(n[0]);
        vol.ny = static_cast<int>(n[1]);
        vol.nz = static_cast<int>(n[2]);
        const std::size_t cells = static_cast<std::size_t>(n[0] * n[1] * n[2]);
        vol.density.resize(cells);
        in.read(reinterpret_cast<char*>(vol.density.data()), static_cast<std::streamsize>(cells * sizeof(float)));
        if (static_cast<std::size_t>(in.gcount()) != cells * sizeof(float))
            r.fail(what + ": the densities end after " + std::to_string(in.gcount()) + " of " +
                   std::to_string(cells * sizeof(float)) + " bytes");
        for (float& f : vol.density) {
            if (swap) f = byteSwapped(f);
            if (!std::isfinite(f)) r.fail(what + ": a density is not finite");
        }
        dump.volumes.push_back(std::move(vol));
    }
    if (in.peek() != std::char_traits<char>::eof())
        r.fail("data after the last volume (the header said " + std::to_string(count) + ")");
    return dump;
}

SmokeDump readSmokeDump(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw DumpError(path + ": cannot open");
    return readSmokeDump(in, path);
}

void writeSmokeDump(const SmokeDump& dump, std::ostream& out) {
    out.precision(std::numeric_limits<double>::max_digits10);
    out << "obscura-smoke-dump 1\ntime " << dump.time << " sigma " << dump.sigma << "\nvolumes " << dump.volumes.size() << "\n";
    const bool swap = !hostLittleEndian();
    for (const DumpVolume& v : dump.volumes) {
        out << "volume " << v.nx << " " << v.ny << " " << v.nz << " " << v.origin.x << " " << v.origin.y << " "
            << v.origin.z << " " << v.cellSize << "\n";
        for (float f : v.density) {
            if (swap) f = byteSwapped(f);
            out.write(reinterpret_cast<const char*>(&f), sizeof f);
        }
    }
}

void writeSmokeDump(const SmokeDump& dump, const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw DumpError(path + ": cannot open for writing");
    writeSmokeDump(dump, out);
    if (!out) throw DumpError(path + ": write failed");
}

}  // namespace obscura::smoke
