#include "gl/gpu_mesh.h"

#include <vector>

#include "gl/gl_context.h"
#include "mesh/draw_order.h"
#include "mesh/media.h"
#include "mesh/uv_texels.h"
#include "mesh/weld.h"
#include "util/error.h"

namespace tsis {
namespace {

// Float attribute `index` of the bound buffer: `size` floats at `offset`
// floats into each vertex of `stride` bytes.
void floatAttribute(GLuint index, GLint size, GLsizei stride, size_t offset) {
    glEnableVertexAttribArray(index);
    // GL takes the buffer offset as a pointer.
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(  // NOLINT(performance-no-int-to-ptr)
                              offset * sizeof(float)));
}

}  // namespace

GpuMesh::GpuMesh(const Mesh& mesh) {
    TSIS_CHECK(mesh.hasNormals());
    TSIS_CHECK(mesh.hasUVs());
    // Each vertex carries its medium's tag (mesh/media.h) to the passes that
    // write positions: the kernels sum light only within a medium.
    const Media media = findMedia(mesh);
    media_ = media.count;
    constexpr int kStride = 9;
    std::vector<float> data;
    data.reserve(mesh.triangles.size() * 3 * kStride);
    for (const glm::uvec3& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            unsigned v = tri[k];
            const glm::vec3& p = mesh.positions[v];
            const glm::vec3& n = mesh.normals[v];
            const glm::vec2& uv = mesh.uvs[v];
            data.insert(data.end(),
                        {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y, mediumTag(media.ofVertex[v])});
        }
    count_ = mesh.triangles.size() * 3;
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                 GL_STATIC_DRAW);
    const GLsizei stride = kStride * sizeof(float);
    floatAttribute(0, 3, stride, 0);  // position
    floatAttribute(1, 3, stride, 3);  // normal
    floatAttribute(2, 2, stride, 6);  // uv
    floatAttribute(4, 1, stride, 8);  // medium tag
    glGenBuffers(1, &ratioVbo_);
    glBindBuffer(GL_ARRAY_BUFFER, ratioVbo_);
    floatAttribute(3, 1, sizeof(float), 0);  // area ratio
    const std::vector<double> ratios = areaRatios(mesh);
    setAreaRatios(std::vector<float>(ratios.begin(), ratios.end()));
    glBindVertexArray(0);

    constexpr int kIndexedStride = 9;
    uploadIndexed(mesh, kIndexedStride, [&](uint32_t v, std::vector<float>& out) {
        const glm::vec3& p = mesh.positions[v];
        const glm::vec3& n = mesh.normals[v];
        const glm::vec2& uv = mesh.uvs[v];
        out.insert(out.end(),
                   {p.x, p.y, p.z, n.x, n.y, n.z, mediumTag(media.ofVertex[v]), uv.x, uv.y});
    });
    closedOutward_ = tsis::closedOutward(mesh);
    glBindVertexArray(0);
    checkGl("GpuMesh upload");
}

GpuMesh::GpuMesh(const Mesh& mesh, PositionsOnly) {
    uploadIndexed(mesh, 3, [&](uint32_t v, std::vector<float>& out) {
        const glm::vec3& p = mesh.positions[v];
        out.insert(out.end(), {p.x, p.y, p.z});
    });
    closedOutward_ = tsis::closedOutward(mesh);
    count_ = mesh.triangles.size() * 3;
    glBindVertexArray(0);
    checkGl("GpuMesh upload (positions)");
}

// The indexed VAO bound, its vertex buffer (`stride` floats a vertex, written
// by `vertex`: indexedAttributes' layout) and the triangles uploaded, both in
// an order llvmpipe sets up faster (mesh/draw_order.h).
void GpuMesh::uploadIndexed(const Mesh& mesh, int stride, const VertexWriter& vertex) {
    const DrawOrder order = coherentDrawOrder(mesh);
    std::vector<float> vertices;
    vertices.reserve(order.vertexOf.size() * size_t(stride));
    for (uint32_t v : order.vertexOf) vertex(v, vertices);
    glGenVertexArrays(1, &indexedVao_);
    glBindVertexArray(indexedVao_);
    glGenBuffers(1, &indexedVbo_);
    glBindBuffer(GL_ARRAY_BUFFER, indexedVbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
                 vertices.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &ebo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(order.triangles.size() * sizeof(glm::uvec3)),
                 order.triangles.data(), GL_STATIC_DRAW);
    indexedStride_ = stride;
    indexedAttributes();
}

// The bound vertex array's attributes and element buffer from the indexed
// buffers: position, then (all but PositionsOnly) normal, medium tag and uv.
void GpuMesh::indexedAttributes() const {
    glBindBuffer(GL_ARRAY_BUFFER, indexedVbo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    const GLsizei stride = indexedStride_ * static_cast<GLsizei>(sizeof(float));
    floatAttribute(0, 3, stride, 0);  // position
    if (indexedStride_ == 3) return;
    floatAttribute(1, 3, stride, 3);  // normal
    floatAttribute(4, 1, stride, 6);  // medium tag
    floatAttribute(2, 2, stride, 7);  // uv (albedo atlas)
}

GpuMesh::~GpuMesh() {
    for (GLuint b : {vbo_, ratioVbo_, indexedVbo_, ebo_})
        if (b) glDeleteBuffers(1, &b);
    for (GLuint a : {vao_, indexedVao_})
        if (a) glDeleteVertexArrays(1, &a);
}

void GpuMesh::draw(GLuint vertexArray) const {
    if (vertexArray) {
        glBindVertexArray(vertexArray);
        indexedAttributes();
    } else {
        glBindVertexArray(indexedVao_);
    }
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count_), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

void GpuMesh::setAreaRatios(const std::vector<float>& perTriangle) {
    TSIS_CHECK_EQ(perTriangle.size() * 3, count_);
    std::vector<float> corners;
    corners.reserve(count_);
    for (float r : perTriangle) corners.insert(corners.end(), {r, r, r});
    glBindBuffer(GL_ARRAY_BUFFER, ratioVbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(float)),
                 corners.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    checkGl("GpuMesh area ratios");
}

void GpuMesh::drawUnrolled() const {
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count_));
    glBindVertexArray(0);
}

}  // namespace tsis
