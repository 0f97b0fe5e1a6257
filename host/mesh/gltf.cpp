// glTF 2.0 (.gltf with embedded or external buffers, .glb), through Debian's
// tinygltf. The default scene's nodes are walked with their transforms and
// every triangle primitive becomes part of one mesh: POSITION, NORMAL and
// TEXCOORD_0 (float, or normalized unsigned byte/short), indices of any
// unsigned width or none, and the primitive's material (gltf_materials.h).
// UVs are kept only when every primitive has them, with v flipped (glTF's
// origin is the image's top left, the atlas' the bottom left, as in OBJ);
// normals likewise. TEXCOORD_0 is also kept as it is, as the texcoords of the
// file's textures, when any primitive has it ((0, 0) on the others). Images
// are never decoded: their encoded bytes are kept for the materials. Every
// accessor is bounds-checked here rather than trusting the file.
//
// A small file can name a huge scene: nodes are instances. Before anything is
// allocated the node graph is checked to be a forest (a node with two parents,
// which the spec forbids, doubles the work at every level; a cycle never ends)
// and the instanced triangles and vertices are counted against a limit
// (maxInstancedTriangles). External files (buffers) are read only from the
// glTF's own folder, links resolved, and only when they are regular files.
#include <tiny_gltf.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <set>

#include "mesh/gltf_materials.h"
#include "mesh/mesh_io.h"
#include "mesh/parse_util.h"
#include "mesh/repair.h"
#include "util/input_file.h"

namespace tsis {

namespace {

using namespace meshparse;

constexpr int kMaxNodeDepth = 64;  // deeper hierarchies are refused (and cycles)

// Images are not decoded here: their bytes are kept (gltf::ImageBytes) for
// the materials' textures.
bool keepImageBytes(tinygltf::Image*, const int index, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void* user) {
    auto& images = *static_cast<gltf::ImageBytes*>(user);
    if (index < 0 || size < 0) return true;
    if (images.size() <= static_cast<size_t>(index)) images.resize(static_cast<size_t>(index) + 1);
    images[static_cast<size_t>(index)].assign(reinterpret_cast<const char*>(bytes),
                                              static_cast<size_t>(size));
    return true;
}

// Without a folder (parsing from memory), files a glTF names are not read.
bool noFile(const std::string&, void*) {
    return false;
}
std::string samePath(const std::string& path, void*) {
    return path;
}
bool noRead(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
    if (err) *err = "external file '" + path + "' is not read when parsing from memory";
    return false;
}
bool noWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
}

// With a folder: files inside it only (util/input_file.h assetFile, unless
// --allow-outside-assets), regular files of at most kMaxMeshFileBytes.
// tinygltf joins the (decoded) URI to the folder (and then to "."); "../",
// an absolute path or a link that leads out is refused.
struct Folder {
    std::filesystem::path root;  // canonical
};
bool anyFile(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);  // ReadWholeFile says why one is refused
}
bool readInside(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                void* user) {
    const std::filesystem::path& root = static_cast<const Folder*>(user)->root;
    try {
        const std::string file =
            assetFile(root.string(), std::filesystem::absolute(path).string(), "external file");
        const std::string bytes = readRegularFile(file, "external file");
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const Error& e) {
        if (err) *err = e.what();
        return false;
    }
}

// Instanced triangles a glTF may expand to: $TSIS_MAX_TRIANGLES, else 4 M
// (about 0.5 GB as a mesh; the largest data mesh has 1.9 M). Vertices: 3× that.
uint64_t maxInstancedTriangles(const std::string& name) {
    const char* env = std::getenv("TSIS_MAX_TRIANGLES");
    if (!env || !*env) return 4'000'000;
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(env, &end, 10);
    if (*end != '\0' || errno != 0 || v == 0 || env[0] == '-')
        failIn(name, "TSIS_MAX_TRIANGLES='", env, "' is not a positive integer");
    return std::min<unsigned long long>(v, 1ull << 40);
}

// A dense accessor's elements in memory: element i starts at at(i); the
// checks every reader needs (the accessor, its view and buffer exist, and the
// last element ends inside the view and the buffer).
struct Elements {
    const unsigned char* first = nullptr;
    size_t stride = 0, count = 0;
    const unsigned char* at(size_t i) const { return first + i * stride; }
};

Elements elements(const tinygltf::Model& m, int index, size_t elementBytes, const std::string& name,
                  const char* what) {
    const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(index)];
    if (a.sparse.isSparse) failIn(name, what, ": sparse accessors are not supported");
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(m.bufferViews.size()))
        failIn(name, what, ": no buffer view");
    const tinygltf::BufferView& v = m.bufferViews[static_cast<size_t>(a.bufferView)];
    if (v.buffer < 0 || v.buffer >= static_cast<int>(m.buffers.size()))
        failIn(name, what, ": no buffer");
    const std::vector<unsigned char>& data = m.buffers[static_cast<size_t>(v.buffer)].data;
    const size_t stride = v.byteStride ? v.byteStride : elementBytes;
    const unsigned long long begin = static_cast<unsigned long long>(v.byteOffset) + a.byteOffset;
    const unsigned long long end = std::min<unsigned long long>(
        data.size(), static_cast<unsigned long long>(v.byteOffset) + v.byteLength);
    if (stride < elementBytes || a.count > data.size() ||
        (a.count > 0 &&
         begin + static_cast<unsigned long long>(stride) * (a.count - 1) + elementBytes > end))
        failIn(name, what, ": accessor ", index, " reaches past its buffer");
    return {data.data() + begin, stride, a.count};
}

const tinygltf::Accessor& accessor(const tinygltf::Model& m, int index, const std::string& name,
                                   const char* what) {
    if (index < 0 || index >= static_cast<int>(m.accessors.size()))
        failIn(name, what, ": accessor ", index, " does not exist");
    return m.accessors[static_cast<size_t>(index)];
}

// An accessor's elements as floats, `width` components each (float, or with
// allowNormalized normalized unsigned byte/short).
std::vector<float> readFloats(const tinygltf::Model& m, int index, int width, bool allowNormalized,
                              const std::string& name, const char* what) {
    const tinygltf::Accessor& a = accessor(m, index, name, what);
    if (tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)) != width)
        failIn(name, what, ": expected ", width, " components, the accessor has another type");
    const int type = a.componentType;
    const bool isFloat = type == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool isUnorm = allowNormalized && a.normalized &&
                         (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                          type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (!isFloat && !isUnorm) failIn(name, what, ": component type ", type, " is not supported");
    const size_t component = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(type));
    const Elements e = elements(m, index, component * static_cast<size_t>(width), name, what);
    std::vector<float> out(e.count * static_cast<size_t>(width));
    for (size_t i = 0; i < e.count; ++i)
        for (int c = 0; c < width; ++c) {
            const unsigned char* p = e.at(i) + c * component;
            float f;
            if (isFloat) {
                std::memcpy(&f, p, sizeof f);
            } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                f = static_cast<float>(*p) / 255.0f;
            } else {
                uint16_t u;
                std::memcpy(&u, p, sizeof u);
                f = static_cast<float>(u) / 65535.0f;
            }
            out[i * static_cast<size_t>(width) + static_cast<size_t>(c)] = f;
        }
    return out;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& m, int index, const std::string& name) {
    const tinygltf::Accessor& a = accessor(m, index, name, "indices");
    if (a.type != TINYGLTF_TYPE_SCALAR) failIn(name, "indices: not a scalar accessor");
    const int type = a.componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        failIn(name, "indices: component type ", type, " is not an unsigned integer");
    const size_t size = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(type));
    const Elements e = elements(m, index, size, name, "indices");
    std::vector<uint32_t> out(e.count);
    for (size_t i = 0; i < e.count; ++i) {
        const unsigned char* p = e.at(i);
        uint32_t value = 0;
        if (size == 1) {
            value = *p;
        } else if (size == 2) {
            uint16_t u;
            std::memcpy(&u, p, sizeof u);
            value = u;
        } else {
            std::memcpy(&value, p, sizeof value);
        }
        out[i] = value;
    }
    return out;
}

// The node's matrix or T·R·S; float for the mesh, double for cameras and
// lights (their positions are compared with values printed exactly).
template <typename T>
glm::mat<4, 4, T> localTransform(const tinygltf::Node& n) {
    using M = glm::mat<4, 4, T>;
    using V = glm::vec<3, T>;
    if (n.matrix.size() == 16) {
        M m(1);
        for (int k = 0; k < 16; ++k) glm::value_ptr(m)[k] = static_cast<T>(n.matrix[size_t(k)]);
        return m;  // column-major in both
    }
    M m(1);
    if (n.translation.size() == 3)
        m = glm::translate(m, V(n.translation[0], n.translation[1], n.translation[2]));
    if (n.rotation.size() == 4)
        m *= glm::mat4_cast(
            glm::qua<T>(static_cast<T>(n.rotation[3]), static_cast<T>(n.rotation[0]),
                        static_cast<T>(n.rotation[1]), static_cast<T>(n.rotation[2])));
    if (n.scale.size() == 3) m = glm::scale(m, V(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

// The default scene's nodes must form a forest: every node at most one
// parent, no cycle. Returns the nodes in the order the walk meets them.
std::vector<int> checkForest(const tinygltf::Model& model, const std::vector<int>& roots,
                             const std::string& name) {
    const int n = static_cast<int>(model.nodes.size());
    auto valid = [&](int i) {
        if (i < 0 || i >= n) failIn(name, "node ", i, " does not exist");
    };
    std::vector<int> parent(static_cast<size_t>(n), -1);
    for (int p = 0; p < n; ++p)
        for (int c : model.nodes[static_cast<size_t>(p)].children) {
            valid(c);
            if (parent[static_cast<size_t>(c)] >= 0)
                failIn(name, "node ", c, " has two parents (nodes ", parent[static_cast<size_t>(c)],
                       " and ", p, "); glTF allows one");
            parent[static_cast<size_t>(c)] = p;
        }
    std::vector<char> seen(static_cast<size_t>(n), 0);
    std::vector<int> order;
    std::vector<std::pair<int, int>> stack;  // node, depth
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, 0);
    while (!stack.empty()) {
        const auto [i, depth] = stack.back();
        stack.pop_back();
        valid(i);
        if (seen[static_cast<size_t>(i)])
            failIn(name, "node ", i, " is reached twice (a cycle, or a scene root with a parent)");
        if (depth > kMaxNodeDepth) failIn(name, "nodes nested deeper than ", kMaxNodeDepth);
        seen[static_cast<size_t>(i)] = 1;
        order.push_back(i);
        const std::vector<int>& children = model.nodes[static_cast<size_t>(i)].children;
        for (auto c = children.rbegin(); c != children.rend(); ++c)
            stack.emplace_back(*c, depth + 1);
    }
    return order;
}

// Triangles and vertices of one instance of a primitive, as the file declares
// them (the readers check the accessors later).
std::pair<uint64_t, uint64_t> declaredSize(const tinygltf::Model& m, const tinygltf::Primitive& p) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) return {0, 0};
    auto count = [&](int a) -> uint64_t {
        return a >= 0 && a < static_cast<int>(m.accessors.size())
                   ? m.accessors[static_cast<size_t>(a)].count
                   : 0;
    };
    const auto pos = p.attributes.find("POSITION");
    const uint64_t vertices = pos == p.attributes.end() ? 0 : count(pos->second);
    return {(p.indices >= 0 ? count(p.indices) : vertices) / 3, vertices};
}

// Refuses a scene that instances more than the limit, before any is read:
// O(primitives + nodes), whatever the product.
void checkInstancedSize(const tinygltf::Model& model, const std::vector<int>& meshUses,
                        const std::string& name) {
    std::vector<std::pair<uint64_t, uint64_t>> perMesh(model.meshes.size());
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (const tinygltf::Primitive& p : model.meshes[m].primitives) {
            const auto [t, v] = declaredSize(model, p);
            perMesh[m].first = std::min<uint64_t>(perMesh[m].first + t, UINT64_MAX / 4);
            perMesh[m].second = std::min<uint64_t>(perMesh[m].second + v, UINT64_MAX / 4);
        }
    const uint64_t maxTriangles = maxInstancedTriangles(name);
    uint64_t triangles = 0, vertices = 0;
    for (int mesh : meshUses) {
        if (mesh < 0) continue;
        if (mesh >= static_cast<int>(model.meshes.size()))
            failIn(name, "mesh ", mesh, " does not exist");
        // Both stay below 2⁶² + the limit: they stop at the first that passes it.
        triangles += perMesh[static_cast<size_t>(mesh)].first;
        vertices += perMesh[static_cast<size_t>(mesh)].second;
        if (triangles > maxTriangles)
            failIn(name, "the scene instances more than ", maxTriangles,
                   " triangles (the limit; TSIS_MAX_TRIANGLES raises it)");
        if (vertices > 3 * maxTriangles)
            failIn(name, "the scene instances more than ", 3 * maxTriangles,
                   " vertices (the limit, 3 × TSIS_MAX_TRIANGLES)");
    }
}

struct Builder {
    const tinygltf::Model& model;
    const std::string& name;
    Mesh mesh;
    // Whether each material has a texture (sized when materials are read).
    const std::vector<char>& textured;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs, texcoords;
    std::vector<uint32_t> materialIds;
    bool allNormals = true, allUVs = true, anyTexcoords = false, anyMaterial = false;
    size_t skippedPrimitives = 0, texturedWithoutUV = 0;

    // Nodes checked by checkForest: valid indices, a tree, depth bounded.
    void node(int index, const glm::mat4& parent) {
        const tinygltf::Node& n = model.nodes[static_cast<size_t>(index)];
        const glm::mat4 world = parent * localTransform<float>(n);
        if (n.mesh >= 0) {
            if (n.mesh >= static_cast<int>(model.meshes.size()))
                failIn(name, "mesh ", n.mesh, " does not exist");
            for (const tinygltf::Primitive& p :
                 model.meshes[static_cast<size_t>(n.mesh)].primitives)
                primitive(p, world);
        }
        for (int child : n.children) node(child, world);
    }

    void primitive(const tinygltf::Primitive& p, const glm::mat4& world) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) {
            ++skippedPrimitives;
            return;
        }
        const auto at = [&](const char* key) {
            const auto it = p.attributes.find(key);
            return it == p.attributes.end() ? -1 : it->second;
        };
        if (at("POSITION") < 0) failIn(name, "a triangle primitive has no POSITION");
        const std::vector<float> pos =
            readFloats(model, at("POSITION"), 3, false, name, "POSITION");
        const size_t count = pos.size() / 3;
        const size_t base = mesh.positions.size();
        if (base + count >= UINT32_MAX) failIn(name, "more than 2³² vertices");
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
        for (size_t i = 0; i < count; ++i) {
            const glm::vec4 q = world * glm::vec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0f);
            for (int c = 0; c < 3; ++c) coordinate(q[c], name, base + i);
            mesh.positions.emplace_back(q);
        }
        if (at("NORMAL") >= 0) {
            const std::vector<float> nv = readFloats(model, at("NORMAL"), 3, false, name, "NORMAL");
            if (nv.size() != pos.size()) failIn(name, "NORMAL and POSITION counts differ");
            for (size_t i = 0; i < count; ++i) {
                // Unit again after a scaling transform (zero stays zero: repaired later).
                const glm::vec3 n =
                    normalMatrix * glm::vec3(nv[3 * i], nv[3 * i + 1], nv[3 * i + 2]);
                const float len = glm::length(n);
                normals.push_back(len > 0 ? n / len : n);
            }
        } else {
            allNormals = false;
        }
        if (at("TEXCOORD_0") >= 0) {
            const std::vector<float> t =
                readFloats(model, at("TEXCOORD_0"), 2, true, name, "TEXCOORD_0");
            if (t.size() / 2 != count) failIn(name, "TEXCOORD_0 and POSITION counts differ");
            for (size_t i = 0; i < count; ++i) {
                uvs.emplace_back(t[2 * i], 1.0f - t[2 * i + 1]);
                texcoords.emplace_back(t[2 * i], t[2 * i + 1]);
            }
            anyTexcoords = true;
        } else {
            allUVs = false;
            texcoords.resize(texcoords.size() + count, glm::vec2(0.0f));
        }
        if (p.material >= static_cast<int>(model.materials.size()))
            failIn(name, "material ", p.material, " does not exist");
        const uint32_t material =
            p.material >= 0 ? static_cast<uint32_t>(p.material) : kNoFileMaterial;
        anyMaterial = anyMaterial || p.material >= 0;
        if (p.material >= 0 && static_cast<size_t>(p.material) < textured.size() &&
            textured[static_cast<size_t>(p.material)] && at("TEXCOORD_0") < 0)
            ++texturedWithoutUV;
        std::vector<uint32_t> idx;
        if (p.indices >= 0) {
            idx = readIndices(model, p.indices, name);
        } else {
            idx.resize(count);
            for (size_t i = 0; i < count; ++i) idx[i] = static_cast<uint32_t>(i);
        }
        for (size_t k = 0; k + 2 < idx.size(); k += 3) {
            for (int c = 0; c < 3; ++c)
                if (idx[k + size_t(c)] >= count)
                    failIn(name, "index ", idx[k + size_t(c)], " past the primitive's ", count,
                           " vertices");
            mesh.triangles.emplace_back(base + idx[k], base + idx[k + 1], base + idx[k + 2]);
            materialIds.push_back(material);
        }
    }
};

// The default scene's camera and light nodes (KHR_lights_punctual), in the
// order of the walk. Nodes checked by checkForest.
struct ViewCollector {
    const tinygltf::Model& model;
    const std::string& name;
    FileView view;
    size_t orthographic = 0, degenerate = 0;

    void node(int index, const glm::dmat4& parent) {
        const tinygltf::Node& n = model.nodes[static_cast<size_t>(index)];
        const glm::dmat4 world = parent * localTransform<double>(n);
        if (n.camera >= 0) camera(n, world);
        if (const int l = lightIndex(n, index); l >= 0) light(n, l, world);
        for (int child : n.children) node(child, world);
    }

    // The node's KHR_lights_punctual light, or −1.
    int lightIndex(const tinygltf::Node& n, int index) const {
        const auto it = n.extensions.find("KHR_lights_punctual");
        if (it == n.extensions.end() || !it->second.IsObject() || !it->second.Has("light"))
            return -1;
        const tinygltf::Value& v = it->second.Get("light");
        const int l = v.IsInt() ? v.GetNumberAsInt() : -1;
        if (l < 0 || l >= static_cast<int>(model.lights.size()))
            failIn(name, "node ", index, ": KHR_lights_punctual light ",
                   v.IsNumber() ? concat(v.GetNumberAsDouble()) : "(not a number)",
                   " does not exist");
        return l;
    }

    // The node's −z in the world, and its +y made orthogonal to it; false
    // when the transform flattens them.
    static bool axes(const glm::dmat4& world, glm::dvec3& forward, glm::dvec3& up) {
        const glm::dmat3 r(world);
        forward = r * glm::dvec3(0, 0, -1);
        up = r * glm::dvec3(0, 1, 0);
        const double f = glm::length(forward);
        if (!(f > 0) || !std::isfinite(f)) return false;
        forward /= f;
        up -= forward * glm::dot(up, forward);
        const double u = glm::length(up);
        if (!(u > 1e-12 * glm::length(r * glm::dvec3(0, 1, 0))) || !std::isfinite(u)) return false;
        up /= u;
        return true;
    }

    void camera(const tinygltf::Node& n, const glm::dmat4& world) {
        if (n.camera >= static_cast<int>(model.cameras.size()))
            failIn(name, "camera ", n.camera, " does not exist");
        const tinygltf::Camera& c = model.cameras[static_cast<size_t>(n.camera)];
        if (c.type != "perspective") {
            ++orthographic;
            return;
        }
        FileCamera fc;
        fc.name = !c.name.empty() ? c.name : n.name;
        fc.eye = glm::dvec3(world[3]);
        fc.yfovRadians = c.perspective.yfov;
        if (!axes(world, fc.forward, fc.up) || !std::isfinite(fc.eye.x + fc.eye.y + fc.eye.z)) {
            ++degenerate;
            return;
        }
        view.cameras.push_back(fc);
    }

    void light(const tinygltf::Node& n, int index, const glm::dmat4& world) {
        const tinygltf::Light& l = model.lights[static_cast<size_t>(index)];
        FileLight fl;
        fl.name = !l.name.empty() ? l.name : n.name;
        if (l.type == "point")
            fl.type = FileLight::Type::Point;
        else if (l.type == "directional")
            fl.type = FileLight::Type::Directional;
        else if (l.type == "spot")
            fl.type = FileLight::Type::Spot;
        else
            failIn(name, "light ", index, ": unknown type '", l.type,
                   "' (point, directional or spot)");
        if (!l.color.empty()) {
            if (l.color.size() != 3) failIn(name, "light ", index, ": color needs 3 components");
            fl.color = glm::dvec3(l.color[0], l.color[1], l.color[2]);
        }
        fl.intensity = l.intensity;
        fl.range = l.range;
        if (!(glm::min(fl.color.x, glm::min(fl.color.y, fl.color.z)) >= 0) ||
            !std::isfinite(fl.color.x + fl.color.y + fl.color.z) || !(fl.intensity >= 0) ||
            !std::isfinite(fl.intensity))
            failIn(name, "light ", index, ": color and intensity must be finite and >= 0");
        fl.position = glm::dvec3(world[3]);
        // Scale does not matter to lights; only a directional one needs its axes.
        glm::dvec3 up;
        const bool oriented = axes(world, fl.direction, up);
        if ((!oriented && fl.type == FileLight::Type::Directional) ||
            !std::isfinite(fl.position.x + fl.position.y + fl.position.z)) {
            ++degenerate;
            return;
        }
        view.lights.push_back(fl);
    }
};

// "'a', 'b', 'c' and 2 more": names (or #index when unnamed), at most 3.
std::string nameList(const std::vector<std::string>& names) {
    std::string s;
    for (size_t i = 0; i < names.size() && i < 3; ++i)
        s += concat(i ? ", " : "", "'", names[i].empty() ? concat("#", i) : names[i], "'");
    if (names.size() > 3) s += concat(" and ", names.size() - 3, " more");
    return s;
}

// One note per kind of thing the file has and tsis does not use. With
// `materialsRead`, materials and their textures were read (readMaterials
// noted what of them was not).
void noteIgnoredParts(const tinygltf::Model& model, int scene, const std::string& name,
                      bool materialsRead) {
    auto count = [&](size_t n, const char* one, const char* many, const char* why) {
        if (n) note(name, concat(n, " ", plural(n, one, many), " ignored (", why, ")"));
    };
    if (!model.materials.empty() && !materialsRead) {
        std::vector<std::string> names;
        for (const tinygltf::Material& m : model.materials) names.push_back(m.name);
        const size_t n = names.size();
        note(name, concat(n == 1 ? "material " : concat(n, " materials "), nameList(names),
                          " ignored (the material is --material's)"));
    }
    if ((!model.textures.empty() || !model.images.empty()) && !materialsRead)
        note(name, concat(model.textures.size(), " ",
                          plural(model.textures.size(), "texture", "textures"), " and ",
                          model.images.size(), " ", plural(model.images.size(), "image", "images"),
                          " ignored (not read)"));
    count(model.animations.size(), "animation", "animations", "the scene is drawn unanimated");
    count(model.skins.size(), "skin", "skins", "skinned meshes are drawn unskinned");
    size_t morphed = 0;
    std::vector<std::string> attributes;
    for (const tinygltf::Mesh& m : model.meshes)
        for (const tinygltf::Primitive& p : m.primitives) {
            morphed += !p.targets.empty();
            for (const auto& [key, accessor] : p.attributes)
                if (key != "POSITION" && key != "NORMAL" && key != "TEXCOORD_0" &&
                    std::find(attributes.begin(), attributes.end(), key) == attributes.end())
                    attributes.push_back(key);
        }
    if (morphed)
        note(name,
             concat("morph targets of ", morphed, " ", plural(morphed, "primitive", "primitives"),
                    " ignored (the base shape is drawn)"));
    if (!attributes.empty()) {
        std::sort(attributes.begin(), attributes.end());
        std::string list;
        for (const std::string& a : attributes) list += (list.empty() ? "" : ", ") + a;
        note(name, "vertex attributes ignored: " + list + " (read: POSITION, NORMAL, TEXCOORD_0)");
    }
    // Read, or noted with the materials that use them (readMaterials): a
    // material's extensions, and texture transforms (their textures are
    // either dropped or ignored, with a note).
    std::set<std::string> noted{"KHR_lights_punctual"};
    if (materialsRead) {
        noted.insert("KHR_texture_transform");
        for (const tinygltf::Material& m : model.materials)
            for (const auto& [e, value] : m.extensions) noted.insert(e);
    }
    std::vector<std::string> extensions;
    for (const std::vector<std::string>* list : {&model.extensionsUsed, &model.extensionsRequired})
        for (const std::string& e : *list)
            if (!noted.count(e) &&
                std::find(extensions.begin(), extensions.end(), e) == extensions.end())
                extensions.push_back(e);
    if (!extensions.empty()) {
        std::string list;
        for (const std::string& e : extensions) list += (list.empty() ? "" : ", ") + e;
        note(name, "extensions ignored: " + list);
    }
    if (model.scenes.size() > 1)
        note(name, concat(model.scenes.size() - 1, " other ",
                          plural(model.scenes.size() - 1, "scene", "scenes"),
                          " ignored (the default scene, ", scene, ", is drawn)"));
}

}  // namespace

Mesh parseGLTF(const std::string& bytes, const std::string& name, const std::string& folder,
               FileView* view) {
    if (bytes.empty()) failIn(name, "empty file");
    tinygltf::TinyGLTF loader;
    gltf::ImageBytes images;
    loader.SetImageLoader(keepImageBytes, &images);
    Folder root;
    if (folder.empty()) {
        loader.SetFsCallbacks({noFile, samePath, noRead, noWrite, nullptr});
    } else {
        std::error_code ec;
        root.root = std::filesystem::canonical(folder, ec);
        if (ec) failIn(name, "its folder '", folder, "': ", ec.message());
        loader.SetFsCallbacks({anyFile, samePath, readInside, noWrite, &root});
    }
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    if (bytes.size() > UINT32_MAX) failIn(name, "larger than 4 GiB");
    // tinygltf reports bad files through err, but may throw on some (its
    // JSON parser, allocation): one line either way.
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(
                          &model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                          static_cast<unsigned int>(bytes.size()), folder)
                    : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                 static_cast<unsigned int>(bytes.size()), folder);
    } catch (const std::exception& e) {
        err = e.what();
    }
    if (!ok) {
        // tinygltf's messages may span lines: the first is the reason.
        std::string first = err.substr(0, err.find('\n'));
        failIn(name, "not a valid glTF 2.0 file (", first.empty() ? "no reason given" : first, ")");
    }
    // Materials first: the walk counts textured ones without TEXCOORD_0.
    std::vector<FileMaterial> materials;
    if (view) materials = gltf::readMaterials(model, name, folder, images);
    std::vector<char> textured(materials.size());
    for (size_t m = 0; m < materials.size(); ++m) textured[m] = !materials[m].texturePath.empty();
    Builder b{model, name, {}, textured};
    b.mesh.name = name;  // repair's notes name the file
    ViewCollector views{model, name, {}};
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (scene < static_cast<int>(model.scenes.size())) {
        const std::vector<int>& roots = model.scenes[static_cast<size_t>(scene)].nodes;
        std::vector<int> meshUses;
        for (int n : checkForest(model, roots, name))
            meshUses.push_back(model.nodes[static_cast<size_t>(n)].mesh);
        checkInstancedSize(model, meshUses, name);
        for (int n : roots) b.node(n, glm::mat4(1.0f));
        for (int n : roots) views.node(n, glm::dmat4(1.0));
    } else {
        // No scene: every mesh once, untransformed.
        std::vector<int> meshUses(model.meshes.size());
        for (size_t m = 0; m < meshUses.size(); ++m) meshUses[m] = static_cast<int>(m);
        checkInstancedSize(model, meshUses, name);
        for (size_t m = 0; m < model.meshes.size(); ++m)
            for (const tinygltf::Primitive& p : model.meshes[m].primitives)
                b.primitive(p, glm::mat4(1.0f));
    }
    if (b.skippedPrimitives > 0)
        note(name, std::to_string(b.skippedPrimitives) + " non-triangle " +
                       plural(b.skippedPrimitives, "primitive", "primitives") + " skipped");
    if (b.mesh.triangles.empty()) failIn(name, "no triangles");
    noteIgnoredParts(model, scene, name, view != nullptr);
    if (b.texturedWithoutUV)
        note(name, concat(b.texturedWithoutUV, " ",
                          plural(b.texturedWithoutUV, "primitive", "primitives"),
                          " with a textured material but no TEXCOORD_0: the texture shows its "
                          "(0, 0) corner there"));
    const size_t cameras = views.view.cameras.size(), lights = views.view.lights.size();
    if (views.orthographic)
        note(name, concat(views.orthographic, " orthographic ",
                          plural(views.orthographic, "camera", "cameras"),
                          " ignored (tsis' camera is a pinhole)"));
    if (views.degenerate)
        note(name, concat(views.degenerate, " ",
                          plural(views.degenerate, "camera or light", "cameras or lights"),
                          " ignored (their node's transform is degenerate)"));
    if (view) {
        *view = std::move(views.view);
        view->materials = std::move(materials);
        if (b.anyMaterial) b.mesh.materialIds = std::move(b.materialIds);
    } else if (cameras || lights) {
        note(name,
             concat(cameras, " ", plural(cameras, "camera", "cameras"), " and ", lights, " ",
                    plural(lights, "light", "lights"), " ignored (not read by this command)"));
    }
    if (b.allNormals) b.mesh.normals = std::move(b.normals);
    if (b.allUVs) b.mesh.uvs = std::move(b.uvs);
    if (b.anyTexcoords) b.mesh.texcoords = std::move(b.texcoords);
    repairMesh(b.mesh);
    return b.mesh;
}

}  // namespace tsis
