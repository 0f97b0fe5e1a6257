// Stanford PLY: ascii, binary_little_endian and binary_big_endian. Reads the
// vertex element (x y z, optional nx ny nz and s t / u v / texture_u
// texture_v), the face element's vertex_indices (or vertex_index) list, and
// the tristrips element's vertex_indices (triangle strips, -1 starts a new
// strip); every other element and property is skipped by its declared type.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "mesh/mesh_io.h"
#include "mesh/parse_util.h"
#include "mesh/repair.h"

namespace tsis {

namespace {

using namespace meshparse;

enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };
enum class Format { Ascii, LittleEndian, BigEndian };

bool typeFromName(std::string_view s, Type& t) {
    static const std::pair<const char*, Type> names[] = {
        {"char", Type::I8},    {"int8", Type::I8},     {"uchar", Type::U8},
        {"uint8", Type::U8},   {"short", Type::I16},   {"int16", Type::I16},
        {"ushort", Type::U16}, {"uint16", Type::U16},  {"int", Type::I32},
        {"int32", Type::I32},  {"uint", Type::U32},    {"uint32", Type::U32},
        {"float", Type::F32},  {"float32", Type::F32}, {"double", Type::F64},
        {"float64", Type::F64}};
    for (const auto& [n, type] : names)
        if (s == n) {
            t = type;
            return true;
        }
    return false;
}

size_t typeSize(Type t) {
    switch (t) {
        case Type::I8:
        case Type::U8:
            return 1;
        case Type::I16:
        case Type::U16:
            return 2;
        case Type::I32:
        case Type::U32:
        case Type::F32:
            return 4;
        case Type::F64:
            return 8;
    }
    return 0;
}

struct Property {
    std::string name;
    bool list = false;
    Type count = Type::U8, item = Type::F32;
};

struct Element {
    std::string name;
    unsigned long long count = 0;
    std::vector<Property> props;

    int find(std::string_view n) const {
        for (size_t i = 0; i < props.size(); ++i)
            if (props[i].name == n) return static_cast<int>(i);
        return -1;
    }
};

// Values of the data section, one at a time, as double; every read is bounds
// checked and names the element record it was in when the data runs out.
class Data {
  public:
    Data(std::string_view bytes, size_t firstLine, Format f, const std::string& name)
        : format_(f),
          name_(name),
          tokens_(bytes, firstLine),
          p_(bytes.data()),
          end_(bytes.data() + bytes.size()) {}

    void at(const Element& e, unsigned long long record) {
        element_ = &e;
        record_ = record;
    }

    double read(Type t) {
        if (format_ == Format::Ascii) {
            std::string_view tok;
            if (!tokens_.next(tok)) truncated();
            double v = 0;
            if (!parseDouble(tok, v))
                failAt(name_, tokens_.lineNumber(), "bad number '", tok, "' in ", element_->name,
                       " ", record_);
            return v;
        }
        const size_t n = typeSize(t);
        if (static_cast<size_t>(end_ - p_) < n) truncated();
        unsigned char b[8];
        std::memcpy(b, p_, n);
        p_ += n;
        const bool swap =
            (format_ == Format::BigEndian) != (std::endian::native == std::endian::big);
        if (swap)
            for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
        switch (t) {
            case Type::I8:
                return static_cast<double>(std::bit_cast<int8_t>(b[0]));
            case Type::U8:
                return static_cast<double>(b[0]);
            case Type::I16:
                return load<int16_t>(b);
            case Type::U16:
                return load<uint16_t>(b);
            case Type::I32:
                return load<int32_t>(b);
            case Type::U32:
                return load<uint32_t>(b);
            case Type::F32:
                return load<float>(b);
            case Type::F64:
                return load<double>(b);
        }
        return 0.0;
    }

    // A list's length: a whole number the rest of the data could hold.
    unsigned long long listCount(const Property& p) {
        const double c = read(p.count);
        if (!(c >= 0.0) || std::floor(c) != c)
            failHere("bad list length ", c, " for '", p.name, "'");
        const unsigned long long each = format_ == Format::Ascii ? 2 : typeSize(p.item);
        if (c > static_cast<double>(bytesLeft() + 1) / static_cast<double>(each))
            failHere("list '", p.name, "' claims ", c, " entries, more than the file holds");
        return static_cast<unsigned long long>(c);
    }

    void skip(const Property& p) {
        if (!p.list) {
            read(p.item);
            return;
        }
        const unsigned long long n = listCount(p);
        if (format_ == Format::Ascii) {
            for (unsigned long long i = 0; i < n; ++i) read(p.item);
        } else {
            const unsigned long long bytes = n * typeSize(p.item);  // bounded by listCount
            if (bytes > bytesLeft()) truncated();
            p_ += bytes;
        }
    }

    size_t bytesLeft() const {
        return format_ == Format::Ascii ? tokens_.bytesLeft() : static_cast<size_t>(end_ - p_);
    }
    size_t line() const { return format_ == Format::Ascii ? tokens_.lineNumber() : 0; }

    template <typename... Args>
    [[noreturn]] void failHere(const Args&... args) const {
        if (format_ == Format::Ascii)
            failAt(name_, tokens_.lineNumber(), element_->name, " ", record_, ": ", args...);
        failIn(name_, element_->name, " ", record_, ": ", args...);
    }

  private:
    template <typename T>
    static double load(const unsigned char* b) {
        T v;
        std::memcpy(&v, b, sizeof v);
        return static_cast<double>(v);
    }

    [[noreturn]] void truncated() const {
        failIn(name_, "truncated: the data ends in ", element_->name, " ", record_, " of ",
               element_->count);
    }

    Format format_;
    const std::string& name_;
    Tokens tokens_;
    const char* p_;
    const char* end_;
    const Element* element_ = nullptr;
    unsigned long long record_ = 0;
};

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    size_t dataStart = 0;
    size_t dataLine = 0;  // line number where the data starts (ASCII messages)
};

Header parseHeader(std::string_view text, const std::string& name) {
    Lines lines(text, '\0');
    std::vector<std::string_view> tok;
    if (!lines.next(tok)) failIn(name, "empty file");
    if (tok[0] != "ply") failAt(name, lines.lineNumber(), "not a PLY file (no 'ply' magic)");
    Header h;
    bool haveFormat = false, ended = false;
    while (!ended && lines.next(tok)) {
        const size_t line = lines.lineNumber();
        const std::string_view key = tok[0];
        if (key == "format") {
            if (tok.size() < 2) failAt(name, line, "format line without a format");
            if (tok[1] == "ascii")
                h.format = Format::Ascii;
            else if (tok[1] == "binary_little_endian")
                h.format = Format::LittleEndian;
            else if (tok[1] == "binary_big_endian")
                h.format = Format::BigEndian;
            else
                failAt(name, line, "unknown format '", tok[1], "'");
            haveFormat = true;
        } else if (key == "element") {
            long long count = 0;
            if (tok.size() < 3 || !parseInt(tok[2], count) || count < 0)
                failAt(name, line, "bad element line (want 'element NAME COUNT')");
            h.elements.push_back({std::string(tok[1]), static_cast<unsigned long long>(count), {}});
        } else if (key == "property") {
            if (h.elements.empty()) failAt(name, line, "property before any element");
            Property p;
            if (tok.size() >= 5 && tok[1] == "list") {
                p.list = true;
                if (!typeFromName(tok[2], p.count) || !typeFromName(tok[3], p.item))
                    failAt(name, line, "unknown list type '", tok[2], " ", tok[3], "'");
                if (p.count == Type::F32 || p.count == Type::F64)
                    failAt(name, line, "list length type must be an integer type");
                p.name = tok[4];
            } else if (tok.size() >= 3 && tok[1] != "list") {
                if (!typeFromName(tok[1], p.item))
                    failAt(name, line, "unknown property type '", tok[1], "'");
                p.name = tok[2];
            } else {
                failAt(name, line, "bad property line");
            }
            h.elements.back().props.push_back(p);
        } else if (key == "end_header") {
            ended = true;
        }
        // comment, obj_info and anything unknown: nothing to read.
    }
    if (!ended) failIn(name, "truncated header (no end_header)");
    if (!haveFormat) failIn(name, "header has no format line");
    h.dataStart = text.size() - lines.bytesLeft();
    h.dataLine = lines.lineNumber() + 1;
    return h;
}

// The list property of `e` that holds vertex indices; -1 when none.
int indexList(const Element& e) {
    int p = e.find("vertex_indices");
    if (p < 0) p = e.find("vertex_index");
    return p;
}

// The index that ends a strip: -1, or its bit pattern in an unsigned type.
double stripRestart(Type t) {
    switch (t) {
        case Type::U8:
            return 255.0;
        case Type::U16:
            return 65535.0;
        case Type::U32:
            return 4294967295.0;
        default:
            return -1.0;
    }
}

// Triangles of one strip s0 s1 s2 …: (s0 s1 s2), (s2 s1 s3), (s2 s3 s4), … so
// every triangle keeps the strip's orientation; triangles that repeat a
// vertex (the joins of stitched strips) are left out.
void addStrip(const std::vector<uint32_t>& s, std::vector<glm::uvec3>& triangles) {
    for (size_t i = 2; i < s.size(); ++i) {
        const uint32_t a = s[i - 2], b = s[i - 1], c = s[i];
        if (a == b || b == c || a == c) continue;
        triangles.push_back(i % 2 == 0 ? glm::uvec3(a, b, c) : glm::uvec3(b, a, c));
    }
}

// The least bytes the data section needs for what the header declares
// (saturating), so no count is trusted before it is checked against the file.
unsigned long long leastDataBytes(const Header& h) {
    unsigned long long total = 0;
    for (const Element& e : h.elements) {
        unsigned long long each = 0;
        for (const Property& p : e.props)
            each += h.format == Format::Ascii ? 2 : typeSize(p.list ? p.count : p.item);
        const unsigned long long bytes = minBytes(e.count, each);
        total = bytes > std::numeric_limits<unsigned long long>::max() - total
                    ? std::numeric_limits<unsigned long long>::max()
                    : total + bytes;
    }
    return total;
}

}  // namespace

Mesh parsePLY(const std::string& bytes, const std::string& name) {
    const Header h = parseHeader(bytes, name);
    const Element* vertex = nullptr;
    const Element* face = nullptr;
    const Element* strips = nullptr;
    for (const Element& e : h.elements) {
        if (e.name == "vertex" && !vertex) vertex = &e;
        if (e.name == "face" && !face) face = &e;
        if (e.name == "tristrips" && !strips) strips = &e;
    }
    if (!vertex) failIn(name, "no vertex element");
    if ((!face || face->count == 0) && (!strips || strips->count == 0))
        failIn(name, "no faces (", vertex->count, " vertices and no triangles)");
    if (face && face->count == 0) face = nullptr;
    if (strips && strips->count == 0) strips = nullptr;

    const size_t dataBytes = bytes.size() - h.dataStart;
    const unsigned long long least = leastDataBytes(h);
    if (least > dataBytes + (h.format == Format::Ascii ? 1 : 0))
        failIn(name, "truncated or corrupt: header claims ", vertex->count, " vertices and ",
               face ? face->count : strips->count, face ? " faces" : " strips",
               ", more than the file's ", bytes.size(), " bytes can hold");
    if (vertex->count >= std::numeric_limits<uint32_t>::max())
        failIn(name, "too many vertices (", vertex->count, ")");

    const int px = vertex->find("x"), py = vertex->find("y"), pz = vertex->find("z");
    if (px < 0 || py < 0 || pz < 0) failIn(name, "vertex element lacks x, y or z");
    int pn[3] = {vertex->find("nx"), vertex->find("ny"), vertex->find("nz")};
    const bool hasNormals = pn[0] >= 0 && pn[1] >= 0 && pn[2] >= 0;
    int puv[2] = {-1, -1};
    static const char* uvNames[][2] = {
        {"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
    for (const auto& uv : uvNames)
        if (puv[0] < 0 && vertex->find(uv[0]) >= 0 && vertex->find(uv[1]) >= 0) {
            puv[0] = vertex->find(uv[0]);
            puv[1] = vertex->find(uv[1]);
        }
    const bool hasUVs = puv[0] >= 0;
    for (int i : {px, py, pz, pn[0], pn[1], pn[2], puv[0], puv[1]})
        if (i >= 0 && vertex->props[static_cast<size_t>(i)].list)
            failIn(name, "vertex property '", vertex->props[static_cast<size_t>(i)].name,
                   "' is a list");
    const int pf = face ? indexList(*face) : -1;
    if (face && pf < 0) failIn(name, "face element has no vertex_indices list");
    if (face && !face->props[static_cast<size_t>(pf)].list)
        failIn(name, "face property 'vertex_indices' is not a list");
    const int ps = strips ? indexList(*strips) : -1;
    if (strips && ps < 0) failIn(name, "tristrips element has no vertex_indices list");
    if (strips && !strips->props[static_cast<size_t>(ps)].list)
        failIn(name, "tristrips property 'vertex_indices' is not a list");

    Mesh mesh;
    mesh.name = name;
    const size_t nv = static_cast<size_t>(vertex->count);
    mesh.positions.reserve(nv);  // bounded by the file size above
    if (hasNormals) mesh.normals.reserve(nv);
    if (hasUVs) mesh.uvs.reserve(nv);
    // Faces may be empty lists (one byte each): reserve for what a triangle
    // needs at least (count + 3 indices), growing past it if need be.
    mesh.triangles.reserve(
        static_cast<size_t>(std::min<unsigned long long>(face ? face->count : 0, dataBytes / 4)));

    Data data(std::string_view(bytes).substr(h.dataStart), h.dataLine, h.format, name);
    bool doneV = false, doneF = !face, doneS = !strips;
    size_t shortFaces = 0;
    std::vector<double> values;
    std::vector<uint32_t> strip;
    for (const Element& e : h.elements) {
        if (doneV && doneF && doneS) break;  // what follows is not needed
        if (e.props.empty()) continue;       // no data at all, however large its count
        for (unsigned long long r = 0; r < e.count; ++r) {
            data.at(e, r);
            if (&e == vertex) {
                values.assign(e.props.size(), 0.0);
                for (size_t k = 0; k < e.props.size(); ++k) {
                    if (e.props[k].list)
                        data.skip(e.props[k]);
                    else
                        values[k] = data.read(e.props[k].item);
                }
                auto v = [&](int k) { return values[static_cast<size_t>(k)]; };
                const size_t line = data.line();
                mesh.positions.emplace_back(coordinate(v(px), name, r, line),
                                            coordinate(v(py), name, r, line),
                                            coordinate(v(pz), name, r, line));
                if (hasNormals)
                    mesh.normals.emplace_back(toFloat(v(pn[0])), toFloat(v(pn[1])),
                                              toFloat(v(pn[2])));
                if (hasUVs) {
                    const glm::vec2 uv(toFloat(v(puv[0])), toFloat(v(puv[1])));
                    if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
                        data.failHere("texture coordinate is not finite");
                    mesh.uvs.push_back(uv);
                }
            } else if (&e == face) {
                for (size_t k = 0; k < e.props.size(); ++k) {
                    if (static_cast<int>(k) != pf) {
                        data.skip(e.props[k]);
                        continue;
                    }
                    const unsigned long long n = data.listCount(e.props[k]);
                    Fan fan(mesh.triangles);
                    for (unsigned long long c = 0; c < n; ++c) {
                        const double x = data.read(e.props[k].item);
                        if (!(x >= 0.0 && x < static_cast<double>(nv)) || std::floor(x) != x)
                            data.failHere("vertex index ", x, " out of range (", nv, " vertices)");
                        fan.add(static_cast<uint32_t>(x));
                    }
                    shortFaces += n < 3;
                }
            } else if (&e == strips) {
                for (size_t k = 0; k < e.props.size(); ++k) {
                    if (static_cast<int>(k) != ps) {
                        data.skip(e.props[k]);
                        continue;
                    }
                    const unsigned long long n = data.listCount(e.props[k]);
                    strip.clear();
                    for (unsigned long long c = 0; c < n; ++c) {
                        const double x = data.read(e.props[k].item);
                        if (x == stripRestart(e.props[k].item)) {
                            addStrip(strip, mesh.triangles);
                            strip.clear();
                            continue;
                        }
                        if (!(x >= 0.0 && x < static_cast<double>(nv)) || std::floor(x) != x)
                            data.failHere("vertex index ", x, " out of range (", nv, " vertices)");
                        strip.push_back(static_cast<uint32_t>(x));
                    }
                    addStrip(strip, mesh.triangles);
                }
            } else {
                for (const Property& p : e.props) data.skip(p);
            }
        }
        doneV = doneV || &e == vertex;
        doneF = doneF || &e == face;
        doneS = doneS || &e == strips;
    }
    noteShortFaces(name, shortFaces);
    repairMesh(mesh);
    return mesh;
}

}  // namespace tsis
