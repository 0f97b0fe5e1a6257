// The mesh on the GL side: triangles unindexed (three vertices each) so that a
// per-triangle value, the area ratio A3D/AUV of eq. 3.2, can ride along.
#pragma once

#include "gl/gl.h"
#include "mesh/mesh.h"

namespace tsis {

class GpuMesh {
  public:
    // Layout per vertex: position (3), normal (3), uv (2), area ratio (1).
    explicit GpuMesh(const Mesh& mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    void draw() const;
    size_t vertexCount() const { return count_; }

  private:
    GLuint vao_ = 0, vbo_ = 0;
    size_t count_ = 0;
};

}  // namespace tsis
