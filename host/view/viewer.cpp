#include "view/viewer.h"

// The window is gl_window.h's; here GLFW is only keys and events (GL is gl/gl.h's).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <vector>

#include "compare/heatmap.h"
#include "compare/image_compare.h"
#include "mesh/media.h"
#include "physics/material.h"
#include "render/aov_files.h"
#include "render/method.h"
#include "render/truth_check.h"
#include "util/error.h"
#include "util/output_set.h"
#include "view/background_task.h"
#include "view/camera_control.h"
#include "view/gl_window.h"
#include "view/panel.h"
#include "view/render_worker.h"

namespace tsis {

namespace {

// The nearest-rank q-quantile of `values` (0 when empty).
double percentile(std::vector<double> values, double q) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const auto rank = static_cast<size_t>(std::ceil(q * static_cast<double>(values.size())));
    return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

using Clock = std::chrono::steady_clock;

constexpr float kPanelWidth = 380;
constexpr int kMinWindowHeight = 660;
// The light's auto-orbit: pixels of drag per rendered frame (2°).
constexpr float kAutoOrbitPixels = 0.0349066f / kRadiansPerPixel;
// Wheel notches and size steps of the keys.
constexpr double kSizeStep = 1.25;
// The `truth` command's volumetric budget (two seeds of half each).
constexpr double kViewTruthSeconds = 20;

double secondsBetween(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

int accumulatedFrames(const FrameStats& stats) {
    const double frames = stats.number("accumulated_frames");
    return std::isnan(frames) ? 1 : static_cast<int>(frames);
}

template <typename T>
const T& cycle(const std::vector<T>& list, const T& current, int step) {
    const auto it = std::find(list.begin(), list.end(), current);
    const int n = static_cast<int>(list.size());
    const int i = it == list.end() ? 0 : static_cast<int>(it - list.begin());
    return list[((i + step) % n + n) % n];
}

class Viewer {
  public:
    explicit Viewer(ViewerConfig config);
    ViewerResult run();

  private:
    // One pass of the window's loop, in this order.
    void collect();
    void input();
    void playScript();
    void panel();
    void drawImage();
    void submitIfNeeded();
    void captureScreenshot();
    double waitSeconds() const;

    // Parts of them.
    void onFrame(FrameDone done);
    void onMesh();
    void onReference();
    void compareWithReference();
    void openMesh(const std::string& spec);
    void startReference();
    void changeSize(double factor);
    bool scriptWaiting() const;
    bool busy() const;
    void runCommand(const ScriptCommand& c);
    void writeFile(const std::string& what, const std::string& path,
                   const std::function<void(const std::filesystem::path&)>& write);
    void writeAovs(const std::string& dir);
    void requestAovs(const std::string& dir);
    void report(const std::string& message, bool error);
    void countUiUpdate();

    ViewerConfig config_;
    ViewState state_;
    GlWindow window_;
    std::unique_ptr<RenderWorker> worker_;
    // The frame's mesh: state_.mesh scaled to state_.sizeMm (made again when either changes).
    std::shared_ptr<const Mesh> scaled_, scaledFrom_;
    double scaledSize_ = 0;

    // Frames.
    uint64_t nextId_ = 1;
    bool awaiting_ = false;               // a frame asked for and not yet collected
    bool fitPending_ = false;             // the last frame's transport is being fitted
    std::optional<ViewState> submitted_;  // the view of the last frame asked for
    std::optional<ViewState> shown_;      // the view of the frame on screen
    FrameResult frame_;
    std::string frameError_;
    int accumulated_ = 0;
    bool forceFrame_ = false;  // a frame of the same view (for its AOVs)
    std::optional<std::string> aovPending_;

    // Background work.
    std::unique_ptr<BackgroundTask<ViewMesh>> meshTask_;
    std::string meshTaskSpec_;
    double meshTaskSize_ = 0;
    std::string meshError_;
    const Mesh* objectsOf_ = nullptr;  // the mesh objects_ describes (once a mesh, for the panel)
    std::string objects_, objectsMaterial_;
    FileMaterialLines fileMaterials_;  // the file's materials, for the panel (with objects_)
    std::unique_ptr<BackgroundTask<FrameResult>> referenceTask_;
    ViewState referenceTaskState_;
    Clock::time_point referenceStart_;
    std::optional<FrameResult> reference_;
    ViewState referenceState_;
    std::optional<double> relRmse_;
    // The model's error against volumetric transport (the `truth` command, T):
    // its own Renderer in the background, the view when it was asked.
    void startTruth();
    std::unique_ptr<BackgroundTask<TruthCheck>> truthTask_;
    ViewState truthTaskState_;
    std::optional<TruthCheck> truth_;
    ViewState truthState_;
    double heatScale_ = 0;

    // The panel.
    PanelFields fields_;
    bool panelShown_ = true;
    std::string status_;
    bool statusIsError_ = false;

    // The script.
    size_t scriptNext_ = 0;
    int scriptFrames_ = 0;                           // frames still to render for `frame N`
    std::optional<Clock::time_point> scriptResume_;  // `wait MS`: the next command not before
    std::optional<std::string> screenshotPending_;
    int screenshotDelay_ = 0;

    // Statistics.
    int framesRendered_ = 0;
    Clock::time_point firstFrame_, lastFrame_;
    std::deque<Clock::time_point> recentFrames_;
    std::vector<double> frameMs_;  // every frame's total, for its percentiles
    long long uiUpdates_ = 0;
    Clock::time_point start_ = Clock::now(), bucketStart_ = start_;
    int bucketUpdates_ = 0;
    bool bucketBusy_ = false;
    double minBusyUpdatesPerS_ = -1;
};

Viewer::Viewer(ViewerConfig config)
    : config_(std::move(config)),
      state_(config_.state),
      window_("tsis view", config_.state.options.width + static_cast<int>(kPanelWidth),
              std::max(config_.state.options.height, kMinWindowHeight)) {
    worker_ = std::make_unique<RenderWorker>(config_.clDevice, config_.gl, GlWindow::wake);
    openMesh(state_.meshSpec);
}

void Viewer::report(const std::string& message, bool error) {
    status_ = message;
    statusIsError_ = error;
    if (error && config_.script) fail(message);  // a script's step that fails ends the run
    std::fprintf(stderr, "tsis: view: %s\n", printable(message).c_str());
}

void Viewer::openMesh(const std::string& spec) {
    meshTaskSpec_ = spec;
    meshTaskSize_ = state_.sizeMm;
    auto load = config_.loadMesh;
    const double size = state_.sizeMm;
    meshTask_ = std::make_unique<BackgroundTask<ViewMesh>>(
        [load, spec, size] { return load(spec, size); }, GlWindow::wake);
}

void Viewer::onMesh() {
    std::unique_ptr<BackgroundTask<ViewMesh>> task = std::move(meshTask_);
    try {
        ViewMesh loaded = task->take();
        // The file's camera at start-up (a mesh opened later keeps the view).
        if (loaded.camera && !state_.mesh) state_.camera = state_.home = *loaded.camera;
        state_.objectMaterials =
            std::make_shared<const std::vector<ObjectMaterial>>(std::move(loaded.materials));
        state_.mesh = std::make_shared<Mesh>(std::move(loaded.mesh));
        state_.meshSizeMm = meshTaskSize_;
        state_.meshSpec = meshTaskSpec_;
        meshError_.clear();
    } catch (...) {
        const std::string message = currentErrorMessage();
        if (!state_.mesh) throw Error(message);  // the start-up mesh: nothing to show
        // The old scene stays.
        meshError_ = "cannot open '" + meshTaskSpec_ + "': " + message;
        std::fprintf(stderr, "tsis: view: %s\n", printable(meshError_).c_str());
    }
}

void Viewer::startReference() {
    if (referenceTask_ || !state_.mesh) return;
    referenceTaskState_ = state_;
    referenceStart_ = Clock::now();
    Scene scene = sceneOf(state_, scaledMesh(state_));
    RenderOptions options = state_.options;
    options.method = "reference";
    options.keepAovs = true;
    options.progressive = false;
    const std::string device = config_.clDevice, gl = config_.gl;
    // Its own Renderer: a GL context current on the task's thread, its own CL queue.
    referenceTask_ = std::make_unique<BackgroundTask<FrameResult>>(
        [scene = std::move(scene), options, device, gl] {
            Renderer renderer(device, gl);
            return renderer.render(scene, options);
        },
        GlWindow::wake);
}

void Viewer::startTruth() {
    if (truthTask_ || !state_.mesh) return;
    truthTaskState_ = state_;
    Scene scene = sceneOf(state_, scaledMesh(state_));
    const RenderOptions options = state_.options;
    const std::string device = config_.clDevice, gl = config_.gl;
    truthTask_ = std::make_unique<BackgroundTask<TruthCheck>>(
        [scene = std::move(scene), options, device, gl] {
            Renderer renderer(device, gl);
            return truthCheck(renderer, scene, options, kViewTruthSeconds);
        },
        GlWindow::wake);
}

void Viewer::onReference() {
    std::unique_ptr<BackgroundTask<FrameResult>> task = std::move(referenceTask_);
    try {
        reference_ = task->take();
        referenceState_ = referenceTaskState_;
        if (config_.script)
            std::fprintf(stderr, "tsis: view: reference in %.1f s\n",
                         secondsBetween(referenceStart_, Clock::now()));
    } catch (...) {
        report("reference: " + currentErrorMessage(), true);
        return;
    }
    compareWithReference();
    if (!relRmse_) forceFrame_ = true;  // the frame on screen has no AOVs: render it with them
}

void Viewer::compareWithReference() {
    relRmse_.reset();
    if (!reference_ || !shown_ || !sameScene(*shown_, referenceState_) ||
        frame_.radiosity.channels == 0)
        return;
    Comparison c;
    try {
        c = compareImages(frame_.radiosity, reference_->radiosity, &reference_->coverage, "frame",
                          "reference", "coverage");
    } catch (const Error&) {
        return;  // the object is out of the picture: no error to show
    }
    relRmse_ = c.metrics.relRmse;
    heatScale_ = heatmapScale(c.relError);
    // The heat map: viridis of the relative error where the object is, the frame elsewhere.
    std::vector<uint8_t> rgb = frame_.rgb8;
    for (size_t i = 0; i < c.relError.pixels.size(); ++i) {
        const float e = c.relError.pixels[i];
        if (e < 0) continue;
        const auto colour = heatColour(e / heatScale_);
        std::copy(colour.begin(), colour.end(), rgb.begin() + 3 * i);
    }
    window_.upload(1, frame_.width, frame_.height, rgb);
}

void Viewer::onFrame(FrameDone done) {
    awaiting_ = false;
    fitPending_ = false;
    const Clock::time_point now = Clock::now();
    if (framesRendered_++ == 0) firstFrame_ = now;
    lastFrame_ = now;
    recentFrames_.push_back(now);
    if (recentFrames_.size() > 16) recentFrames_.pop_front();
    if (!done.error.empty()) {
        frameError_ = done.error;
        if (config_.script) fail(done.error);
        return;
    }
    frameError_.clear();
    frame_ = std::move(done.frame);
    frameMs_.push_back(frame_.stats.stageMs("total"));
    shown_ = submitted_;
    accumulated_ = accumulatedFrames(frame_.stats);
    window_.upload(0, frame_.width, frame_.height, frame_.rgb8);
    // Made while its transport is fitted in the background: shown, and the
    // frame with it follows (render_worker.h); the error, the AOVs and a
    // script wait for that one.
    fitPending_ = frame_.stats.number("transport_pending") == 1;
    if (fitPending_) return;
    compareWithReference();
    if (aovPending_ && frame_.radiosity.channels > 0) {
        const std::string dir = *aovPending_;
        aovPending_.reset();
        writeAovs(dir);
    }
}

void Viewer::collect() {
    if (std::optional<FrameDone> done = worker_->take()) onFrame(std::move(*done));
    if (meshTask_ && meshTask_->done()) onMesh();
    if (referenceTask_ && referenceTask_->done()) onReference();
    if (truthTask_ && truthTask_->done()) {
        std::unique_ptr<BackgroundTask<TruthCheck>> task = std::move(truthTask_);
        try {
            truth_ = task->take();
            truthState_ = truthTaskState_;
            if (config_.script)
                std::fprintf(stderr, "tsis: view: truth check %.1f %% (noise %.1f %%)\n",
                             100 * truth_->subtracted, 100 * truth_->noise);
        } catch (...) {
            report("truth check: " + currentErrorMessage(), true);
        }
    }
}

void Viewer::changeSize(double factor) {
    resize(state_, std::clamp(state_.sizeMm * factor, kMinSizeMm, kMaxSizeMm));
}

void Viewer::input() {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureMouse) {
        const bool shift = io.KeyShift, ctrl = io.KeyCtrl;
        const float dx = io.MouseDelta.x, dy = io.MouseDelta.y;
        const bool moved = dx != 0 || dy != 0;
        if (moved && (io.MouseDown[1] || (io.MouseDown[0] && shift))) {
            if (!state_.lights.empty())
                state_.lights[0].vec = turnAboutY(state_.lights[0].vec, dx, -dy);
        } else if (moved && (io.MouseDown[2] || (io.MouseDown[0] && ctrl))) {
            state_.camera = panCamera(state_.camera, dx, dy, state_.options.height);
        } else if (moved && io.MouseDown[0]) {
            state_.camera = orbitCamera(state_.camera, dx, dy);
        }
        if (io.MouseWheel != 0)
            state_.camera = zoomCamera(state_.camera, io.MouseWheel, 0.05f * float(state_.sizeMm),
                                       50.0f * float(state_.sizeMm));
    }
    if (io.WantCaptureKeyboard) return;
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    if (pressed(GLFW_KEY_ESCAPE) || pressed(GLFW_KEY_Q)) window_.requestClose();
    if (pressed(GLFW_KEY_H) || pressed(GLFW_KEY_F1)) panelShown_ = !panelShown_;
    if (pressed(GLFW_KEY_SPACE)) state_.autoOrbit = !state_.autoOrbit;
    if (pressed(GLFW_KEY_P)) state_.progressive = !state_.progressive;
    if (pressed(GLFW_KEY_T)) fields_.heatmap = !fields_.heatmap;
    if (pressed(GLFW_KEY_R)) state_.camera = state_.home;
    if (pressed(GLFW_KEY_M))
        state_.options.method = cycle(methodNames(), state_.options.method, io.KeyShift ? -1 : 1);
    if (pressed(GLFW_KEY_N)) {
        std::vector<std::string> names;
        for (const Material& m : presetMaterials()) names.push_back(m.name);
        state_.material = presetMaterial(cycle(names, state_.material.name, io.KeyShift ? -1 : 1));
    }
    if (pressed(GLFW_KEY_EQUAL) || pressed(GLFW_KEY_KP_ADD)) changeSize(kSizeStep);
    if (pressed(GLFW_KEY_MINUS) || pressed(GLFW_KEY_KP_SUBTRACT)) changeSize(1.0 / kSizeStep);
    if (pressed(GLFW_KEY_C)) startReference();
    if (pressed(GLFW_KEY_T)) startTruth();
    if (pressed(GLFW_KEY_S)) screenshotPending_ = fields_.screenshotPath;
}

bool Viewer::busy() const {
    return meshTask_ || referenceTask_ || truthTask_ || awaiting_;
}

// A script's next command waits for the frame of the view so far, the frames
// `frame N` asked for, the background work and a screenshot in hand.
bool Viewer::scriptWaiting() const {
    if (scriptResume_ && Clock::now() < *scriptResume_) return true;
    return busy() || fitPending_ || scriptFrames_ > 0 || forceFrame_ || aovPending_ ||
           screenshotPending_ || (state_.mesh && (!submitted_ || !sameFrame(*submitted_, state_)));
}

void Viewer::runCommand(const ScriptCommand& c) {
    using Kind = ScriptCommand::Kind;
    switch (c.kind) {
        case Kind::Frame:
            scriptFrames_ += static_cast<int>(c.x);
            break;
        case Kind::Wait:
            scriptResume_ = Clock::now() + std::chrono::milliseconds(static_cast<int>(c.x));
            break;
        case Kind::Orbit:
            state_.camera = orbitCamera(state_.camera, c.x, c.y);
            break;
        case Kind::Pan:
            state_.camera = panCamera(state_.camera, c.x, c.y, state_.options.height);
            break;
        case Kind::Zoom:
            state_.camera = zoomCamera(state_.camera, c.x, 0.05f * float(state_.sizeMm),
                                       50.0f * float(state_.sizeMm));
            break;
        case Kind::LightDrag:
            if (!state_.lights.empty())
                state_.lights[0].vec = turnAboutY(state_.lights[0].vec, c.x, -c.y);
            break;
        case Kind::Set:
            setParameter(state_, c.name, c.value);
            break;
        case Kind::Panel:
            panelShown_ = c.on;
            break;
        case Kind::Heatmap:
            fields_.heatmap = c.on;
            break;
        case Kind::OpenMesh:
            openMesh(c.value);
            break;
        case Kind::Reference:
            startReference();
            break;
        case Kind::Truth:
            startTruth();
            break;
        case Kind::Screenshot:
            screenshotPending_ = c.value;
            screenshotDelay_ = 1;  // ImGui lays a changed panel out over two frames
            break;
        case Kind::Save:
            writeFile("image", c.value, [&](const std::filesystem::path& f) {
                writeImage8(f.string(), frame_.width, frame_.height, 3, frame_.rgb8);
            });
            break;
        case Kind::Aov:
            requestAovs(c.value);
            break;
        case Kind::Close:
            window_.requestClose();
            break;
    }
}

void Viewer::playScript() {
    if (!config_.script) return;
    const std::vector<ScriptCommand>& script = *config_.script;
    while (scriptNext_ < script.size() && !scriptWaiting() && !window_.closeRequested()) {
        const ScriptCommand& c = script[scriptNext_++];
        try {
            runCommand(c);
        } catch (const Error& e) {
            fail("script line ", c.line, ": ", e.what());
        }
    }
    if (scriptNext_ == script.size() && !scriptWaiting())
        config_.script.reset();  // the mouse's turn
}

void Viewer::panel() {
    if (!panelShown_) return;
    PanelInfo info;
    if (state_.mesh) {
        if (objectsOf_ != state_.mesh.get() || objectsMaterial_ != state_.material.name) {
            objectsOf_ = state_.mesh.get();
            objectsMaterial_ = state_.material.name;
            objects_ = objectsSummary(*state_.mesh, state_);
            fileMaterials_ = fileMaterialLines(*state_.mesh, state_);
        }
        info.fileMaterials = fileMaterials_.lines;
        info.sceneMaterialUsed = fileMaterials_.sceneMaterialUsed;
        // The objects: separate solids, light never crossing between them.
        info.mesh = concat(state_.meshSpec, "  (", state_.mesh->triangles.size(), " triangles; ",
                           objects_, ")");
    } else
        info.mesh = "loading " + meshTaskSpec_;
    info.frameMsP99 = percentile(frameMs_, 0.99);
    if (recentFrames_.size() > 1)
        info.fps = double(recentFrames_.size() - 1) /
                   std::max(1e-9, secondsBetween(recentFrames_.front(), recentFrames_.back()));
    info.accumulated = accumulated_;
    info.stats = frame_.width > 0 ? &frame_.stats : nullptr;
    info.frameError = frameError_;
    if (awaiting_ || fitPending_) info.frameProgress = worker_->progress();
    info.meshLoading = meshTask_ != nullptr;
    if (meshTask_) info.meshProgress = meshTask_->progress();
    info.meshError = meshError_;
    info.referenceRunning = referenceTask_ != nullptr;
    if (referenceTask_) {
        info.referenceProgress = referenceTask_->progress();
        info.referenceSeconds = secondsBetween(referenceStart_, Clock::now());
    }
    info.relRmse = relRmse_;
    info.truthRunning = truthTask_ != nullptr;
    if (truth_) info.truthError = truth_->subtracted, info.truthNoise = truth_->noise;
    info.truthStale = truth_ && !sameScene(truthState_, state_);
    info.heatScale = heatScale_;
    info.referenceStale = reference_ && !sameScene(referenceState_, state_);
    info.status = status_;
    info.statusIsError = statusIsError_;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    PanelActions a =
        drawPanel(state_, fields_, info, display.x - kPanelWidth, kPanelWidth, display.y);
    if (config_.script) return;  // a script's run is its commands alone
    if (a.openMesh) openMesh(fields_.meshPath);
    if (a.reference) startReference();
    if (a.screenshot) screenshotPending_ = fields_.screenshotPath;
    if (a.save && frame_.width > 0)
        writeFile("image", fields_.savePath, [&](const std::filesystem::path& f) {
            writeImage8(f.string(), frame_.width, frame_.height, 3, frame_.rgb8);
        });
    if (a.aov) requestAovs(fields_.aovDir);
}

void Viewer::drawImage() {
    if (frame_.width == 0) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float areaW = io.DisplaySize.x - (panelShown_ ? kPanelWidth : 0.0f);
    const float areaH = io.DisplaySize.y;
    // 1:1 when it fits (top left), else scaled down to fit.
    const float scale = std::min({1.0f, areaW / float(frame_.width), areaH / float(frame_.height)});
    const bool heat = relRmse_ && fields_.heatmap;
    ImGui::GetBackgroundDrawList()->AddImage(
        // ImGui takes a GL texture name as a pointer-sized id.
        reinterpret_cast<ImTextureID>(  // NOLINT(performance-no-int-to-ptr)
            static_cast<intptr_t>(window_.texture(heat ? 1 : 0))),
        ImVec2(0, 0), ImVec2(frame_.width * scale, frame_.height * scale));
    if (meshTask_ && !state_.mesh) {
        const WorkProgress p = meshTask_->progress();
        ImGui::GetForegroundDrawList()->AddText(
            ImVec2(12, 12), IM_COL32(230, 230, 230, 255),
            concat("loading ", meshTaskSpec_, "  ", p.label, " ", int(100 * p.fraction), "%")
                .c_str());
    }
}

void Viewer::submitIfNeeded() {
    if (!state_.mesh || awaiting_) return;
    const std::string& method = state_.options.method;
    const bool sampling = state_.progressive && drawsSamples(method);
    const bool script = config_.script.has_value();
    const bool changed = !submitted_ || !sameFrame(*submitted_, state_);
    const bool more = script ? scriptFrames_ > 0
                             : state_.autoOrbit || (sampling && accumulated_ < state_.maxFrames);
    if (!changed && !more && !forceFrame_) return;
    if (state_.autoOrbit && !state_.lights.empty() && (!script || scriptFrames_ > 0))
        state_.lights[0].vec = turnAboutY(state_.lights[0].vec, kAutoOrbitPixels, 0);
    if (script && scriptFrames_ > 0) --scriptFrames_;
    // A sampling method's last frame before the view rests keeps its AOVs,
    // so that "AOVs" and the reference's error need no frame of their own
    // (which would add a sample set to the mean on screen). Another method
    // renders the view again when they are asked for (requestAovs),
    // so its frames skip the AOVs' read-backs and may read B on the GL side
    // (docs/design.md §6).
    const int frameCount = changed ? 1 : accumulated_ + 1;
    const bool last = sampling && (script ? scriptFrames_ == 0
                                          : !state_.autoOrbit && frameCount >= state_.maxFrames);
    forceFrame_ = false;
    if (scaledFrom_ != state_.mesh || scaledSize_ != state_.sizeMm) {
        scaled_ = scaledMesh(state_);
        scaledFrom_ = state_.mesh;
        scaledSize_ = state_.sizeMm;
    }
    FrameJob job;
    job.id = nextId_++;
    job.mesh = scaled_;
    job.scene = sceneOf(state_, nullptr);
    job.options = state_.options;
    job.options.progressive = sampling;
    const bool referenceHere = (reference_ && sameScene(referenceState_, state_)) ||
                               (referenceTask_ && sameScene(referenceTaskState_, state_));
    job.options.keepAovs = aovPending_.has_value() || referenceHere || last;
    submitted_ = state_;
    awaiting_ = true;
    worker_->submit(std::move(job));
}

void Viewer::writeFile(const std::string& what, const std::string& path,
                       const std::function<void(const std::filesystem::path&)>& write) {
    try {
        OutputSet outputs;
        outputs.add(path);
        requireImageFormat(outputs, path);  // both are images (save, screenshot)
        outputs.write(path, write);
        outputs.commit();
        report(concat("wrote ", what, " ", path), false);
    } catch (const Error& e) {
        report(e.what(), true);
    }
}

void Viewer::writeAovs(const std::string& dir) {
    try {
        OutputSet outputs;
        addAovOutputs(outputs, dir);
        writeAovOutputs(outputs, dir, frame_);
        outputs.commit();
        report("wrote the AOVs into " + dir, false);
    } catch (const Error& e) {
        report(e.what(), true);
    }
}

// The AOVs of the frame on screen when it has them and shows the view, else
// of a frame rendered again with them.
void Viewer::requestAovs(const std::string& dir) {
    if (frame_.radiosity.channels > 0 && shown_ && sameFrame(*shown_, state_)) {
        writeAovs(dir);
        return;
    }
    aovPending_ = dir;
    forceFrame_ = true;
}

void Viewer::captureScreenshot() {
    if (!screenshotPending_ || screenshotDelay_-- > 0) return;
    const std::string path = *screenshotPending_;
    screenshotPending_.reset();
    int w = 0, h = 0;
    const std::vector<uint8_t> rgb = window_.readPixels(w, h);
    writeFile("screenshot", path,
              [&](const std::filesystem::path& f) { writeImage8(f.string(), w, h, 3, rgb); });
}

double Viewer::waitSeconds() const {
    if (screenshotPending_ || forceFrame_ || (config_.script && !scriptWaiting())) return 0.0;
    // Progress bars move while work runs (≥ 20 updates a second); input and
    // finished work wake the loop at once.
    return busy() || config_.script ? 1.0 / 30.0 : 0.5;
}

void Viewer::countUiUpdate() {
    ++uiUpdates_;
    ++bucketUpdates_;
    bucketBusy_ = bucketBusy_ || meshTask_ || referenceTask_;
    const Clock::time_point now = Clock::now();
    const double s = secondsBetween(bucketStart_, now);
    if (s < 1.0) return;
    if (bucketBusy_) {
        const double rate = bucketUpdates_ / s;
        minBusyUpdatesPerS_ = minBusyUpdatesPerS_ < 0 ? rate : std::min(minBusyUpdatesPerS_, rate);
    }
    bucketStart_ = now;
    bucketUpdates_ = 0;
    bucketBusy_ = false;
}

ViewerResult Viewer::run() {
    Clock::time_point updateStart = Clock::now();
    while (!window_.closeRequested()) {
        // The wait counts from the last update's start: the period includes drawing.
        const double wait = waitSeconds() - secondsBetween(updateStart, Clock::now());
        window_.waitEvents(std::max(wait, 0.0));
        updateStart = Clock::now();
        collect();
        window_.beginFrame();
        if (!config_.script) input();
        playScript();
        panel();
        drawImage();
        submitIfNeeded();
        window_.draw();
        captureScreenshot();
        window_.present();
        countUiUpdate();
    }
    ViewerResult result;
    result.state = state_;
    Json stats = Json::object();
    stats["frames"] = framesRendered_;
    const double span = secondsBetween(firstFrame_, lastFrame_);
    stats["fps"] = framesRendered_ > 1 && span > 0 ? (framesRendered_ - 1) / span : 0.0;
    const double seconds = secondsBetween(start_, Clock::now());
    stats["seconds"] = seconds;
    stats["ui_updates"] = uiUpdates_;
    stats["ui_updates_per_s"] = seconds > 0 ? uiUpdates_ / seconds : 0.0;
    stats["min_ui_updates_per_s_while_busy"] =
        minBusyUpdatesPerS_ < 0 ? Json() : Json(minBusyUpdatesPerS_);
    // Spikes: a session's frames by their renderer time (p99 against the median).
    if (!frameMs_.empty()) {
        stats["frame_ms_median"] = percentile(frameMs_, 0.5);
        stats["frame_ms_p99"] = percentile(frameMs_, 0.99);
        stats["frame_ms_max"] = percentile(frameMs_, 1.0);
        stats["frame_ms"] = frameMs_;  // in order: which frame spiked
    }
    if (relRmse_) stats["reference_rel_rmse"] = *relRmse_;
    if (truth_) stats["truth_check_rel_rmse"] = truth_->subtracted;
    if (frame_.width > 0) stats["last_frame"] = frame_.stats.toJson();
    result.stats = stats;
    return result;
}

}  // namespace

ViewerResult runViewer(ViewerConfig config) {
    Viewer viewer(std::move(config));
    return viewer.run();
}

}  // namespace tsis
