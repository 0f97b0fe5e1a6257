// The mesh on the GL side, twice: indexed (positions and normals of the shared
// vertices) for the camera and light views, where llvmpipe's vertex cache
// shades each vertex once instead of once per triangle corner (both listed in
// mesh/draw_order.h's order, which it sets up fastest); and unindexed
// (three vertices per triangle) for the atlas pass, so that a per-triangle
// value, the area ratio A3D/AUV of eq. 3.2, can ride along (in a buffer of
// its own: the atlas' resolution corrects it, mesh/uv_texels.h).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "gl/gl.h"
#include "mesh/mesh.h"

namespace tsis {

class GpuMesh {
  public:
    // Attributes: 0 position, 1 normal, 2 uv, 4 medium tag (mesh/media.h);
    // unindexed only: 3 area ratio.
    explicit GpuMesh(const Mesh& mesh);
    // Positions and triangles only, for a light's depth (mesh/lod.h): draw()
    // alone is valid, the other attributes read their defaults.
    struct PositionsOnly {};
    GpuMesh(const Mesh& mesh, PositionsOnly);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    // Indexed: positions, normals, uvs. `vertexArray`: 0 for the mesh's own;
    // else one of the current context, which need not be the one that made
    // this mesh (vertex arrays are not shared between contexts:
    // gl/gl_worker.h), its attributes set here.
    void draw(GLuint vertexArray = 0) const;
    void drawUnrolled() const;  // unindexed, with uv and area ratio (the atlas pass)
    // The area ratio of each triangle for drawUnrolled (A3D/AUV until set:
    // texelAreaRatios gives the one for an atlas resolution).
    void setAreaRatios(const std::vector<float>& perTriangle);
    uint32_t media() const { return media_; }  // separate solids (mesh/media.h)
    // The triangles a pass sets up: all, or with back faces culled about half.
    size_t trianglesSetUp(bool culled) const { return count_ / 3 / (culled ? 2 : 1); }
    // Closed and wound outward (mesh/weld.h): a light's depth may cull back faces.
    bool closedOutward() const { return closedOutward_; }

  private:
    GLuint vao_ = 0, vbo_ = 0, ratioVbo_ = 0;           // unindexed
    GLuint indexedVao_ = 0, indexedVbo_ = 0, ebo_ = 0;  // indexed
    size_t count_ = 0;
    int indexedStride_ = 0;  // floats a vertex of the indexed buffer
    // Appends the floats of the mesh's vertex v.
    using VertexWriter = std::function<void(uint32_t v, std::vector<float>& out)>;
    void uploadIndexed(const Mesh& mesh, int stride, const VertexWriter& vertex);
    void indexedAttributes() const;
    uint32_t media_ = 1;
    bool closedOutward_ = false;
};

}  // namespace tsis
