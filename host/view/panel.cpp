#include "view/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/ggx.h"
#include "physics/material.h"
#include "render/method.h"
#include "util/error.h"

namespace tsis {

namespace {

const ImVec4 kErrorColour(1.0f, 0.45f, 0.4f, 1.0f);

void errorText(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

void progressLine(const WorkProgress& p, const char* what) {
    char text[256];
    std::snprintf(text, sizeof text, "%s %.0f%%", p.label.empty() ? what : p.label.c_str(),
                  100.0 * p.fraction);
    ImGui::ProgressBar(static_cast<float>(p.fraction), ImVec2(-1, 0), text);
}

// A combo over `names`; true when the choice changed.
bool comboOf(const char* label, std::string& value, const std::vector<std::string>& names) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const std::string& n : names)
            if (ImGui::Selectable(n.c_str(), n == value)) {
                changed = n != value;
                value = n;
            }
        ImGui::EndCombo();
    }
    return changed;
}

// A power-of-two resolution in [lo, hi]; `autoLabel` adds 0 = automatic.
void resolutionCombo(const char* label, int& value, int lo, int hi, const char* autoLabel) {
    char current[32];
    std::snprintf(current, sizeof current, "%d", value);
    if (!ImGui::BeginCombo(label, value == 0 && autoLabel ? autoLabel : current)) return;
    if (autoLabel && ImGui::Selectable(autoLabel, value == 0)) value = 0;
    for (int r = lo; r <= hi; r *= 2) {
        std::snprintf(current, sizeof current, "%d", r);
        if (ImGui::Selectable(current, r == value)) value = r;
    }
    ImGui::EndCombo();
}

// σ per channel in mm⁻¹ on a log slider; true when changed.
bool sigmaSliders(const char* label, glm::dvec3& sigma, float lo, float hi) {
    float v[3] = {float(sigma.x), float(sigma.y), float(sigma.z)};
    if (!ImGui::SliderFloat3(label, v, lo, hi, "%.4g", ImGuiSliderFlags_Logarithmic)) return false;
    sigma = glm::dvec3(std::max(v[0], lo), std::max(v[1], lo), std::max(v[2], lo));
    return true;
}

void settings(ViewState& s, const PanelInfo& info) {
    comboOf("method", s.options.method, methodNames());
    // The file's materials are its own (σ from the file, its albedo or
    // texture); the sliders set the material of the objects without one.
    if (!info.fileMaterials.empty()) {
        ImGui::Text("the file's materials:");
        for (const std::string& line : info.fileMaterials) ImGui::BulletText("%s", line.c_str());
        ImGui::TextDisabled(info.sceneMaterialUsed
                                ? "the sliders: the objects without a file material"
                                : "the sliders: no object (each has a file material)");
    }
    std::vector<std::string> presets;
    for (const Material& m : presetMaterials()) presets.push_back(m.name);
    std::string material = s.material.name;
    if (comboOf("material", material, presets)) s.material = presetMaterial(material);
    bool custom = sigmaSliders("sigma_s' /mm", s.material.sigmaSPrime, 0.01f, 100.0f);
    custom |= sigmaSliders("sigma_a /mm", s.material.sigmaA, 1e-4f, 10.0f);
    float eta = float(s.material.eta);
    if (ImGui::SliderFloat("eta", &eta, 1.01f, 2.5f, "%.3f")) {
        s.material.eta = eta;
        custom = true;
    }
    if (custom) s.material.name = "custom";
    float size = float(s.sizeMm);
    if (ImGui::SliderFloat("size mm", &size, float(kMinSizeMm), float(kMaxSizeMm), "%.4g",
                           ImGuiSliderFlags_Logarithmic))
        resize(s, std::clamp(double(size), kMinSizeMm, kMaxSizeMm));
    ImGui::SliderInt("N samples", &s.options.samples, 1, 16384, "%d", ImGuiSliderFlags_Logarithmic);
    s.options.samples = std::max(1, s.options.samples);
    // The display: one exposure for every frame (--auto-exposure re-exposes each).
    // Roughness: each object's from its file until the slider is moved, then
    // one for all (the box turns back to the file's).
    bool fromFile = s.options.roughness < 0;
    if (ImGui::Checkbox("file roughness", &fromFile))
        s.options.roughness = fromFile ? -1.0f : float(kDefaultRoughness);
    float roughness = fromFile ? float(kDefaultRoughness) : s.options.roughness;
    if (ImGui::SliderFloat("roughness", &roughness, float(kMinRoughness), 1.0f, "%.2f"))
        s.options.roughness = std::clamp(roughness, float(kMinRoughness), 1.0f);
    ImGui::SliderFloat("exposure EV", &s.options.exposure, -10.0f, 10.0f, "%+.1f");
    s.options.exposure = std::clamp(s.options.exposure, -30.0f, 30.0f);
    resolutionCombo("atlas res", s.options.atlasResolution, 64, 4096, "auto");
    resolutionCombo("light res", s.options.lightResolution, 256, 4096, "auto");
    ImGui::Checkbox("auto-orbit light", &s.autoOrbit);
    ImGui::Checkbox("progressive", &s.progressive);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    ImGui::SliderInt("##frames", &s.maxFrames, 1, 1024, "up to %d frames",
                     ImGuiSliderFlags_Logarithmic);
    s.maxFrames = std::max(1, s.maxFrames);
}

void frameLine(const PanelInfo& info) {
    ImGui::Text("%.1f fps   frame %.1f ms (p99 %.1f)   %d frame%s averaged", info.fps,
                info.stats ? info.stats->stageMs("total") : 0.0, info.frameMsP99, info.accumulated,
                info.accumulated == 1 ? "" : "s");
    if (!info.frameProgress.label.empty()) progressLine(info.frameProgress, "frame");
    if (!info.frameError.empty()) errorText(info.frameError);
}

// The last frame's stages as bars of their share of its time.
void stageBars(const PanelInfo& info) {
    if (!info.stats || !ImGui::CollapsingHeader("stages", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const double total = std::max(1e-9, info.stats->stageMs("total"));
    for (const FrameStats::Stage& st : info.stats->stages) {
        if (st.name == "total") continue;
        char text[128];
        std::snprintf(text, sizeof text, "%s %.2f ms", st.name.c_str(), st.ms);
        ImGui::ProgressBar(static_cast<float>(std::clamp(st.ms / total, 0.0, 1.0)), ImVec2(-1, 0),
                           text);
    }
}

void reference(const PanelInfo& info, PanelFields& fields, PanelActions& actions) {
    if (info.referenceRunning) {
        ImGui::Text("reference: %.0f s", info.referenceSeconds);
        progressLine(info.referenceProgress, "reference");
    } else {
        actions.reference = ImGui::Button("compute reference");
    }
    if (info.relRmse) {
        ImGui::Text("relative RMSE %.3f%%", 100.0 * *info.relRmse);
        ImGui::Checkbox("heat map", &fields.heatmap);
        if (fields.heatmap) {
            ImGui::SameLine();
            ImGui::Text("0 .. %.3g%% (viridis)", 100.0 * info.heatScale);
        }
    } else if (info.referenceStale) {
        ImGui::TextDisabled("the reference is of an earlier view");
    }
    // The model's own error (key T, script `truth`).
    if (info.truthRunning)
        ImGui::Text("truth check: volumetric transport running");
    else if (info.truthError)
        ImGui::Text("model vs volumetric %.1f%% (noise %.1f%%)%s", 100.0 * *info.truthError,
                    100.0 * info.truthNoise, info.truthStale ? ", earlier view" : "");
}

void files(const PanelInfo& info, PanelFields& fields, PanelActions& actions) {
    actions.screenshot = ImGui::Button("screenshot");
    ImGui::SameLine();
    ImGui::InputText("##shot", fields.screenshotPath, sizeof fields.screenshotPath);
    actions.save = ImGui::Button("save image");
    ImGui::SameLine();
    ImGui::InputText("##save", fields.savePath, sizeof fields.savePath);
    actions.aov = ImGui::Button("AOVs (EXR)");
    ImGui::SameLine();
    ImGui::InputText("##aov", fields.aovDir, sizeof fields.aovDir);
    if (!info.status.empty()) {
        if (info.statusIsError)
            errorText(info.status);
        else
            ImGui::TextWrapped("%s", info.status.c_str());
    }
}

void meshSection(const PanelInfo& info, PanelFields& fields, PanelActions& actions) {
    ImGui::TextWrapped("%s", info.mesh.c_str());
    const bool enter = ImGui::InputText("##mesh", fields.meshPath, sizeof fields.meshPath,
                                        ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    actions.openMesh =
        (ImGui::Button("open mesh") || enter) && fields.meshPath[0] != '\0' && !info.meshLoading;
    if (info.meshLoading) progressLine(info.meshProgress, "loading");
    if (!info.meshError.empty()) errorText(info.meshError);
}

// --env: a map file (loaded at once: the transfer is kept per mesh, so only
// the first frame on a mesh casts rays), its turn about +y and its scale.
void environmentSection(ViewState& s, PanelFields& fields) {
    const bool enter = ImGui::InputText("##env", fields.envPath, sizeof fields.envPath,
                                        ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("open env") || enter) && fields.envPath[0] != '\0') {
        try {
            setParameter(s, "env", fields.envPath);
            fields.envError.clear();
        } catch (const Error& e) {
            fields.envError = e.what();
        }
    }
    if (!fields.envError.empty()) errorText(fields.envError);
    if (!s.env) return;
    float rotate = static_cast<float>(s.env.rotateDegrees);
    if (ImGui::SliderFloat("env turn deg", &rotate, -180.0f, 180.0f, "%.0f"))
        s.env.rotateDegrees = rotate;
    float intensity = static_cast<float>(s.env.intensity);
    if (ImGui::SliderFloat("env intensity", &intensity, 0.01f, 100.0f, "%.3g",
                           ImGuiSliderFlags_Logarithmic))
        s.env.intensity = intensity;
    if (!s.lights.empty() && ImGui::Button("env alone (remove the lights)")) s.lights.clear();
}

}  // namespace

PanelActions drawPanel(ViewState& state, PanelFields& fields, const PanelInfo& info, float x,
                       float width, float height) {
    PanelActions actions;
    ImGui::SetNextWindowPos(ImVec2(x, 0));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("tsis view", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-110);
    meshSection(info, fields, actions);
    ImGui::Separator();
    settings(state, info);
    ImGui::Separator();
    environmentSection(state, fields);
    ImGui::Separator();
    frameLine(info);
    ImGui::Separator();
    reference(info, fields, actions);
    ImGui::Separator();
    files(info, fields, actions);
    stageBars(info);
    ImGui::Separator();
    ImGui::TextDisabled(
        "drag: orbit  right/shift: light  middle/ctrl: pan\n"
        "wheel: zoom  space: auto-orbit  h: panel  r: reset\n"
        "m/n: next method/material  +/-: size  c: reference\n"
        "p: progressive  t: heat map  s: screenshot  q: quit");
    ImGui::PopItemWidth();
    ImGui::End();
    return actions;
}

}  // namespace tsis
