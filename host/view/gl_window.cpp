#include "view/gl_window.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <string>

#include "image/image_io.h"
#include "util/error.h"
#include "util/loaded_libraries.h"

namespace tsis {

namespace {

std::string gLastGlfwError;

void onGlfwError(int, const char* description) {
    gLastGlfwError = description ? description : "";
}

}  // namespace

// The window context's GL calls, through pointers GLFW loads for it (the
// prototypes of GL/gl.h name only the types; calling them would reach OSMesa).
struct GlWindow::Gl {
    decltype(&::glViewport) Viewport;
    decltype(&::glClearColor) ClearColor;
    decltype(&::glClear) Clear;
    decltype(&::glGenTextures) GenTextures;
    decltype(&::glDeleteTextures) DeleteTextures;
    decltype(&::glBindTexture) BindTexture;
    decltype(&::glTexParameteri) TexParameteri;
    decltype(&::glTexImage2D) TexImage2D;
    decltype(&::glPixelStorei) PixelStorei;
    decltype(&::glReadBuffer) ReadBuffer;
    decltype(&::glReadPixels) ReadPixels;

    Gl() {
        load(Viewport, "glViewport");
        load(ClearColor, "glClearColor");
        load(Clear, "glClear");
        load(GenTextures, "glGenTextures");
        load(DeleteTextures, "glDeleteTextures");
        load(BindTexture, "glBindTexture");
        load(TexParameteri, "glTexParameteri");
        load(TexImage2D, "glTexImage2D");
        load(PixelStorei, "glPixelStorei");
        load(ReadBuffer, "glReadBuffer");
        load(ReadPixels, "glReadPixels");
    }
    template <typename F>
    static void load(F& f, const char* name) {
        f = reinterpret_cast<F>(glfwGetProcAddress(name));
        if (!f) fail("cannot open a window: the window's OpenGL has no ", name);
    }
};

GlWindow::GlWindow(const std::string& title, int width, int height) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        fail("no display: set DISPLAY or run under xvfb-run; 'tsis render' works without one");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = gLastGlfwError;
        glfwTerminate();
        fail("cannot open a window with an OpenGL 3.3 core context: ", why);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    // GLFW loads the X GL libraries (and they their driver) with dlopen, and
    // glfwTerminate unloads them (util/loaded_libraries.h).
    keepLoadedLibrariesMapped();
    try {
        gl_ = std::make_unique<Gl>();
    } catch (...) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw;
    }
    gl_->GenTextures(2, textures_);
    for (unsigned t : textures_) {
        gl_->BindTexture(GL_TEXTURE_2D, t);
        gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini left in the working folder
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
}

GlWindow::~GlWindow() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    gl_->DeleteTextures(2, textures_);
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlWindow::closeRequested() const {
    return glfwWindowShouldClose(window_);
}

void GlWindow::requestClose() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlWindow::waitEvents(double timeoutSeconds) {
    if (timeoutSeconds > 0)
        glfwWaitEventsTimeout(timeoutSeconds);
    else
        glfwPollEvents();
}

void GlWindow::wake() {
    glfwPostEmptyEvent();
}

void GlWindow::beginFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void GlWindow::draw() {
    ImGui::Render();
    int w = 0, h = 0;
    framebufferSize(w, h);
    gl_->Viewport(0, 0, w, h);
    gl_->ClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    gl_->Clear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

std::vector<uint8_t> GlWindow::readPixels(int& width, int& height) const {
    framebufferSize(width, height);
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_->ReadBuffer(GL_BACK);
    gl_->ReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    flipRows(rgb, width, height, 3);  // GL's row 0 is the bottom
    return rgb;
}

void GlWindow::present() {
    glfwSwapBuffers(window_);
}

void GlWindow::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
}

unsigned GlWindow::texture(int slot) const {
    return textures_[slot];
}

void GlWindow::upload(int slot, int width, int height, const std::vector<uint8_t>& rgb) {
    TSIS_CHECK_EQ(rgb.size(), static_cast<size_t>(width) * height * 3);
    gl_->BindTexture(GL_TEXTURE_2D, textures_[slot]);
    gl_->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Row 0 of the image is the texture's v = 0: ImGui draws it at the top.
    gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width, height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                    rgb.data());
}

}  // namespace tsis
