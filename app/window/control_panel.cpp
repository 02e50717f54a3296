#include "window/control_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <imgui.h>

#include "rbsim/integrate/integrator.h"
#include "rbsim/mass/mass_properties.h"

namespace rbsim::app {

namespace {

constexpr float kPanelWidthFraction = 0.3f;  // of the image width
constexpr float kMinTimeStepSlider = 1e-4f;  // [s]: the dt slider's range
constexpr float kMaxTimeStepSlider = 0.05f;  // [s]
constexpr float kGravitySliderRange = 20.0f; // [m/s^2] either way per component

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

void appendPush(std::vector<float>& series, float value) {
  if (series.size() == kPlotSamples) series.erase(series.begin());
  series.push_back(value);
}

void plot(const char* label, const std::vector<float>& series, const char* unit) {
  if (series.empty()) return;
  const auto [low, high] = std::minmax_element(series.begin(), series.end());
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%.4g %s", static_cast<double>(series.back()), unit);
  ImGui::PlotLines(label, series.data(), static_cast<int>(series.size()), 0, overlay, *low,
                   *high > *low ? *high : *low + 1.0f, ImVec2(0.0f, 2.2f * ImGui::GetTextLineHeight()));
}

// A physics slider: assigns only when the user lets go, so a drag restarts the scene once.
template <typename Widget>
void physicsEdit(PanelRequests& out, const std::string& path, Widget&& widget, const std::string& value) {
  widget();
  if (ImGui::IsItemDeactivatedAfterEdit()) out.assignments.push_back({path, value, true});
}

void viewToggle(PanelRequests& out, const char* label, const char* key, bool current) {
  bool value = current;
  if (ImGui::Checkbox(label, &value)) out.assignments.push_back({std::string("view.") + key, value ? "true" : "false", false});
}

}  // namespace

void PlotHistory::add(const RigidBody& body) {
  appendPush(speed, static_cast<float>(body.velocity().norm()));
  appendPush(angularSpeed, static_cast<float>(body.angularVelocity().norm()));
  appendPush(kineticEnergy, static_cast<float>(body.kineticEnergy()));
}

void PlotHistory::clear() {
  speed.clear();
  angularSpeed.clear();
  kineticEnergy.clear();
}

PanelRect panelRect(int imageWidth, int imageHeight) {
  const float margin = std::round(0.015f * static_cast<float>(imageHeight)) + 4.0f;
  const float width = std::round(kPanelWidthFraction * static_cast<float>(imageWidth));
  return {static_cast<float>(imageWidth) - width - margin, margin, width, static_cast<float>(imageHeight) - 2.0f * margin};
}

PanelRequests drawControlPanel(const PanelView& view, int imageWidth, int imageHeight) {
  PanelRequests out;
  const Scene& scene = *view.scene;
  const World& world = *view.world;
  const PanelRect rect = panelRect(imageWidth, imageHeight);
  ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
  ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Controls", nullptr, flags)) {
    ImGui::End();
    return out;
  }
  ImGui::PushItemWidth(-0.45f * rect.width);

  if (!view.scenes.empty()) {
    const std::string current = std::filesystem::path(view.phases[view.phase]).stem().string();
    if (ImGui::BeginCombo("scene", current.c_str())) {
      for (const SceneEntry& entry : view.scenes) {
        if (ImGui::Selectable(entry.name.c_str(), entry.path == view.phases[view.phase])) out.scene = entry.path;
        if (ImGui::IsItemHovered() && !entry.title.empty()) ImGui::SetTooltip("%s", entry.title.c_str());
      }
      ImGui::EndCombo();
    }
  }
  if (view.phases.size() > 1) {
    const std::string current = std::filesystem::path(view.phases[view.phase]).stem().string();
    if (ImGui::BeginCombo("phase", current.c_str())) {
      for (std::size_t i = 0; i < view.phases.size(); ++i) {
        const std::string name = std::filesystem::path(view.phases[i]).stem().string();
        if (ImGui::Selectable(name.c_str(), i == view.phase)) out.phase = static_cast<int>(i);
      }
      ImGui::EndCombo();
    }
  }
  ImGui::Text("t = %.3f s, step %llu", world.time(), static_cast<unsigned long long>(world.stepCount()));
  if (ImGui::Button(view.paused ? "Run (space)" : "Pause (space)")) out.togglePause = true;
  ImGui::SameLine();
  if (ImGui::Button("Step (s)")) out.step = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset (r)")) out.reset = true;
  if (ImGui::Button(view.recording ? "Stop recording" : "Record video")) out.toggleRecording = true;
  ImGui::SameLine();
  if (ImGui::Button("Copy as command (c)")) out.copyCommand = true;
  float speed = static_cast<float>(view.speed);
  if (ImGui::SliderFloat("speed", &speed, static_cast<float>(kMinPlaybackSpeed), static_cast<float>(kMaxPlaybackSpeed),
                         "%.2fx", ImGuiSliderFlags_Logarithmic)) {
    out.speed = speed;
  }
  // Frames slower than 1/fps to simulate and draw hold the playback below the speed asked for.
  if (!view.paused && view.shownRate < 0.95 * view.speed) {
    ImGui::TextDisabled("shown at %.2fx: frames take longer than 1/fps", view.shownRate);
  }
  if (view.recording) ImGui::TextWrapped("recording to %s", view.recordingPath.c_str());
  if (!view.message.empty()) ImGui::TextWrapped("%s", view.message.c_str());

  if (ImGui::CollapsingHeader("Physics (restarts at t = 0)", ImGuiTreeNodeFlags_DefaultOpen)) {
    float dt = static_cast<float>(scene.settings.timeStep);
    physicsEdit(out, "world.dt", [&] {
      ImGui::SliderFloat("dt [s]", &dt, kMinTimeStepSlider, kMaxTimeStepSlider, "%.5f", ImGuiSliderFlags_Logarithmic);
    }, number(dt));
    const std::vector<std::string> names = integratorNames();
    const std::string integrator = integratorName(scene.settings.integrator);
    if (ImGui::BeginCombo("integrator", integrator.c_str())) {
      for (const std::string& name : names) {
        if (ImGui::Selectable(name.c_str(), name == integrator)) out.assignments.push_back({"world.integrator", quoted(name), true});
      }
      ImGui::EndCombo();
    }
    const std::string solver = contactSolverName(scene.settings.solver);
    if (ImGui::BeginCombo("solver", solver.c_str())) {
      for (const char* name : {"soft-step", "pgs", "lcp"}) {
        if (ImGui::Selectable(name, solver == name)) out.assignments.push_back({"world.solver", quoted(name), true});
      }
      ImGui::EndCombo();
    }
    const std::string inertia = inertiaMethodName(scene.settings.inertia);
    if (ImGui::BeginCombo("inertia", inertia.c_str())) {
      for (const char* name : {"cube", "exact"}) {
        if (ImGui::Selectable(name, inertia == name)) out.assignments.push_back({"world.inertia", quoted(name), true});
      }
      ImGui::EndCombo();
    }
    float gravity[3] = {static_cast<float>(scene.settings.gravity.x()), static_cast<float>(scene.settings.gravity.y()),
                        static_cast<float>(scene.settings.gravity.z())};
    physicsEdit(out, "world.gravity", [&] {
      ImGui::SliderFloat3("gravity", gravity, -kGravitySliderRange, kGravitySliderRange, "%.2f");
    }, "[" + number(gravity[0]) + "," + number(gravity[1]) + "," + number(gravity[2]) + "]");
    const BodyDef& selected = scene.bodies[scene.view.selected];
    const std::string body = "bodies." + selected.name + ".";
    ImGui::TextDisabled("material of %s", selected.name.c_str());
    float restitution = static_cast<float>(selected.material.restitution);
    physicsEdit(out, body + "restitution", [&] { ImGui::SliderFloat("restitution", &restitution, 0.0f, 1.0f, "%.2f"); },
                number(restitution));
    float staticFriction = static_cast<float>(selected.material.staticFriction);
    physicsEdit(out, body + "friction_static", [&] { ImGui::SliderFloat("mu static", &staticFriction, 0.0f, 1.5f, "%.2f"); },
                number(staticFriction));
    float kineticFriction = static_cast<float>(selected.material.kineticFriction);
    physicsEdit(out, body + "friction_kinetic", [&] { ImGui::SliderFloat("mu kinetic", &kineticFriction, 0.0f, 1.5f, "%.2f"); },
                number(kineticFriction));
  }

  if (ImGui::CollapsingHeader("Drawing", ImGuiTreeNodeFlags_DefaultOpen)) {
    viewToggle(out, "AABBs", "aabbs", scene.view.aabbs);
    ImGui::SameLine();
    viewToggle(out, "contacts", "contacts", scene.view.contacts);
    ImGui::SameLine();
    viewToggle(out, "axes", "axes", scene.view.axes);
    viewToggle(out, "wireframe", "wireframe", scene.view.wireframe);
    ImGui::SameLine();
    viewToggle(out, "grid", "grid", scene.view.grid);
    ImGui::SameLine();
    viewToggle(out, "variables", "overlay", scene.view.overlay);
  }

  if (ImGui::CollapsingHeader("Selected body", ImGuiTreeNodeFlags_DefaultOpen)) {
    const std::string name = scene.bodies[scene.view.selected].name;
    if (ImGui::BeginCombo("body", name.c_str())) {
      for (const BodyDef& def : scene.bodies) {
        if (ImGui::Selectable(def.name.c_str(), def.name == name)) out.assignments.push_back({"view.selected", quoted(def.name), false});
      }
      ImGui::EndCombo();
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("left: pick and drag a body (or orbit), right: orbit, middle: pan, wheel: zoom");
    ImGui::PopStyleColor();
    plot("|v| [m/s]", view.history->speed, "m/s");
    plot("|omega|", view.history->angularSpeed, "rad/s");
    plot("kinetic", view.history->kineticEnergy, "J");
  }

  ImGui::PopItemWidth();
  ImGui::End();
  return out;
}

}  // namespace rbsim::app
