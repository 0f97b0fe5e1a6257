// The window of `tsis view`: GLFW on X, an OpenGL 3.3 core context for
// presenting (Mesa on X or any desktop driver) and Dear ImGui through its GLFW
// and OpenGL 3 backends.
//
// This context is not the renderer's. The renderer's GL calls go through its
// own context's table (gl/gl.h), and the gl* symbols the binary links are
// OSMesa's; so the few GL calls made here go through pointers GLFW loads for
// the window's own context, and ImGui's backend loads its own the same way. The
// Renderer lives on another thread (view/render_worker.h) with its EGL or
// OSMesa context current there.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace tsis {

class GlWindow {
  public:
    // Opens the window (width × height pixels) and starts ImGui. Throws
    // tsis::Error "no display: ..." when there is no X display to open it on.
    GlWindow(const std::string& title, int width, int height);
    ~GlWindow();
    GlWindow(const GlWindow&) = delete;
    GlWindow& operator=(const GlWindow&) = delete;

    bool closeRequested() const;
    void requestClose();
    // Handles the pending events, first waiting up to timeoutSeconds for one
    // (0: no wait).
    void waitEvents(double timeoutSeconds);
    // Ends a waitEvents early; any thread may call it.
    static void wake();

    void beginFrame();  // a new ImGui frame
    // Draws the ImGui frame over the background colour; the picture is then
    // on the back buffer until present().
    void draw();
    // The back buffer as drawn: RGB, row 0 = top.
    std::vector<uint8_t> readPixels(int& width, int& height) const;
    void present();

    // The framebuffer's size in pixels.
    void framebufferSize(int& width, int& height) const;

    // An RGB8 texture ImGui can draw (ImTextureID is its GL name).
    unsigned texture(int slot) const;
    // Fills texture `slot` (0 or 1) with an RGB image, row 0 = top.
    void upload(int slot, int width, int height, const std::vector<uint8_t>& rgb);

  private:
    struct Gl;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<Gl> gl_;
    unsigned textures_[2] = {0, 0};
};

}  // namespace tsis
