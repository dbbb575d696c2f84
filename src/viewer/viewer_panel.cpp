// The viewer's Dear ImGui panel. Its option widgets are made from the option table
// (deferred/option_table.h), one per entry by kind with the entry's help as its tooltip, so an
// option added to the table appears here with the name `render` and `set` use, and nothing in
// this file changes.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include "viewer/scissor_overlay.h"
#include "viewer/viewer_state.h"

namespace dsr {

namespace {

// One widget for one table entry; a change is queued in st.pending.
void option_widget(ViewerState& st, const RenderOption& o) {
    const std::string value = o.get(st.options);
    auto request = [&](const std::string& v) {
        if (v != value) st.pending.emplace_back(&o, v);
    };
    switch (o.kind) {
        case OptionKind::on_off:
        case OptionKind::toggle: {
            bool on = value == "on";
            if (ImGui::Checkbox(o.name.c_str(), &on)) request(on ? "on" : "off");
            break;
        }
        case OptionKind::choice: {
            if (ImGui::BeginCombo(o.name.c_str(), value.c_str())) {
                for (const std::string& v : o.values)
                    if (ImGui::Selectable(v.c_str(), v == value)) request(v);
                ImGui::EndCombo();
            }
            break;
        }
        case OptionKind::number: {
            // The slider edits a copy; the option changes when the slider is let go (each change
            // builds the shader's programs anew). An entry that also takes a word (exposure: auto)
            // has a checkbox for it, as the integer entries below.
            const bool is_word = !o.values.empty() && value == o.values.front();
            if (!o.values.empty()) {
                const float width = ImGui::CalcItemWidth(), x0 = ImGui::GetCursorPosX();
                bool word = is_word;
                if (ImGui::Checkbox((o.values.front() + "##" + o.name).c_str(), &word)) request(word ? o.values.front() : "0");
                ImGui::SameLine();
                ImGui::SetNextItemWidth(std::max(40.0f, width - (ImGui::GetCursorPosX() - x0)));
            }
            static std::map<std::string, float> editing;
            const auto it = editing.find(o.name);
            float f = it != editing.end() ? it->second : is_word ? 0.0f : std::strtof(value.c_str(), nullptr);
            ImGui::SliderFloat(o.name.c_str(), &f, o.lo, o.hi, is_word && it == editing.end() ? value.c_str() : "%.2f");
            if (ImGui::IsItemDeactivatedAfterEdit()) {
                char buf[32];
                std::snprintf(buf, sizeof buf, "%g", double(f));
                request(buf);
                editing.erase(o.name);
            } else if (ImGui::IsItemActive()) {
                editing[o.name] = f;
            } else {
                editing.erase(o.name);
            }
            break;
        }
        case OptionKind::integer: {  // as number: applied when the slider is let go
            // An entry that also takes a word (tile-size: auto) shows the word, not a number, and a
            // checkbox to go back to it; dragging the slider sets a number.
            const bool has_word = !o.values.empty();
            const bool is_word = has_word && std::find(o.values.begin(), o.values.end(), value) != o.values.end();
            if (has_word) {
                const float width = ImGui::CalcItemWidth(), x0 = ImGui::GetCursorPosX();
                bool word = is_word;
                if (ImGui::Checkbox((o.values.front() + "##" + o.name).c_str(), &word))
                    request(word ? o.values.front() : std::to_string(int(o.lo)));
                ImGui::SameLine();
                ImGui::SetNextItemWidth(std::max(40.0f, width - (ImGui::GetCursorPosX() - x0)));  // the column stays
            }
            static std::map<std::string, int> editing;
            const auto it = editing.find(o.name);
            int n = it != editing.end() ? it->second : is_word ? int(o.lo) : std::atoi(value.c_str());
            const bool shows_word = is_word && it == editing.end();
            ImGui::SliderInt(o.name.c_str(), &n, int(o.lo), int(o.hi), shows_word ? value.c_str() : "%d");
            if (ImGui::IsItemDeactivatedAfterEdit()) {
                request(std::to_string(n));
                editing.erase(o.name);
            } else if (ImGui::IsItemActive()) {
                editing[o.name] = n;
            } else {
                editing.erase(o.name);
            }
            break;
        }
        case OptionKind::subset: {
            // --no-skip: a checkbox per member, ticked when the skip is off.
            ImGui::TextWrapped("%s (ticked: skip off)", o.name.c_str());
            std::vector<std::string> off;
            if (value != "none") {
                size_t a = 0;
                while (a <= value.size()) {
                    size_t b = value.find(',', a);
                    if (b == std::string::npos) b = value.size();
                    if (b > a) off.push_back(value.substr(a, b - a));
                    a = b + 1;
                }
            }
            ImGui::Indent();
            for (const std::string& m : o.values) {
                bool in = std::find(off.begin(), off.end(), m) != off.end();
                if (ImGui::Checkbox(m.c_str(), &in)) {
                    std::vector<std::string> next;
                    for (const std::string& k : o.values) {
                        const bool was = std::find(off.begin(), off.end(), k) != off.end();
                        if (k == m ? in : was) next.push_back(k);
                    }
                    std::string v;
                    for (const std::string& k : next) v += (v.empty() ? "" : ",") + k;
                    request(v.empty() ? "none" : v);
                }
            }
            ImGui::Unindent();
            break;
        }
    }
}

std::string count_text(std::optional<long long> n) { return n ? std::to_string(*n) : std::string("n/a"); }

}  // namespace

// The panel's width: 30% of the window, at most 360 px, at least what a line of options needs
// (240 px) where the window has room; its height the window's, scrolling inside.
static float panel_width(int w) { return std::min(std::max(0.3f * float(w), std::min(240.0f, float(w) - 16)), 360.0f); }

void draw_panel(ViewerState& st, const DeferredShader& ds, const Scene& frame_scene, int w, int h) {
    // Placed and sized every frame, so it follows the window: as tall as its content, at most the
    // window's height (then it scrolls). The title bar's arrow collapses it, F1 hides it.
    const float pw = panel_width(w);
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(pw, 0), ImVec2(pw, std::max(40.0f, float(h) - 16)));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("dsr view  (F1 hides)", &st.panel,
                      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove)) {
        ImGui::End();
        return;
    }
    ImGui::TextWrapped("%s", st.renderer.c_str());  // "llvmpipe (LLVM 15.0.6, 256 bits), GL 4.5 (Compatibility ...)"
    const Paths& p = ds.paths();
    ImGui::TextWrapped("%dx%d  depth %s  timing %s", w, h, p.depth.c_str(), timing_name(st.last.timing));
    ImGui::Checkbox("animate lights (L)", &st.animate);
    ImGui::Checkbox("scissor overlay (O)", &st.overlay);
    ImGui::TextWrapped("camera speed %.3g/s (scroll), R resets, F frames the scene", double(st.fly.speed));

    // Both sections start collapsed: the first window shows the image, not the panel.
    if (ImGui::CollapsingHeader("frame")) {
        const StageTimes& m = st.last.ms;
        const std::pair<const char*, double> stages[] = {{"geometry", m.geometry}, {"ambient", m.ambient},
                                                         {"lights", m.lights},     {"bloom", m.bloom},
                                                         {"aa", m.aa},             {"final", m.final},
                                                         {"frame", m.frame}};
        if (ImGui::BeginTable("stages", 2, ImGuiTableFlags_SizingFixedFit)) {
            for (const auto& [name, ms] : stages) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(name);
                ImGui::TableNextColumn();
                ImGui::Text("%8.2f ms", ms);
            }
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted("loop");  // the previous frame's: this one is still being drawn
            ImGui::TableNextColumn();
            ImGui::Text("%8.2f ms", st.loop_ms);
            ImGui::EndTable();
        }
        ImGui::TextWrapped("loop: the last frame's, with the panel and the swap");
        const FrameStats& s = st.last;
        ImGui::TextWrapped("lights %d: %d drawn, %d culled", s.lights.total, s.lights.drawn, s.lights.culled);
        ImGui::TextWrapped("light_fragments   %s", count_text(s.lights.counted_fragments()).c_str());
        ImGui::TextWrapped("light_invocations %s", count_text(s.lights.invocations).c_str());
        ImGui::TextWrapped("light_evaluations %s", count_text(s.lights.evaluations).c_str());
        ImGui::TextWrapped("ideal             %s%s", count_text(st.ideal).c_str(),
                    st.ideal ? "  (once a second)" : "  (depth-texture path only)");
        if (st.ideal && *st.ideal > 0 && s.lights.evaluations)
            ImGui::TextWrapped("evaluations / ideal %.3f", double(*s.lights.evaluations) / double(*st.ideal));
        ImGui::TextWrapped("scissor_pixels    %lld", s.lights.scissor_pixels);

        std::vector<float> frame_ms, lights_ms;
        for (const FrameSample& f : st.history) {
            frame_ms.push_back(float(f.frame_ms));
            lights_ms.push_back(float(f.lights_ms));
        }
        float top = 1;
        for (float v : frame_ms) top = std::max(top, v);
        if (!frame_ms.empty()) {
            ImGui::PlotLines("frame ms", frame_ms.data(), int(frame_ms.size()), 0, "last 5 s", 0, top * 1.1f,
                             ImVec2(0, 60));
            ImGui::PlotLines("lights ms", lights_ms.data(), int(lights_ms.size()), 0, nullptr, 0, top * 1.1f,
                             ImVec2(0, 40));
        }
    }
    // P-buffer 0's luminance (docs/hdr.md), from the reduced copy the final stage reads for
    // --exposure auto: log2 of each block's mean, with float accumulation or --exposure auto.
    if (ImGui::CollapsingHeader("light (P-buffer 0)", ImGuiTreeNodeFlags_DefaultOpen)) {
        const ShaderOptions& o = st.options.shader;
        ImGui::TextWrapped("accum %s, tonemap %s, exposure x%.3f%s", accum_format_name(o.hdr.accum),
                           tone_map_name(o.hdr.tonemap), double(st.exposure_scale), o.hdr.exposure_auto ? " (auto)" : "");
        if (!st.luminance_histogram.empty()) {
            float top = 1;
            for (float v : st.luminance_histogram) top = std::max(top, v);
            char over[64];
            std::snprintf(over, sizeof over, "log2 L %g..%g, %.1f%% above 1", double(ViewerState::kHistogramLo),
                          double(ViewerState::kHistogramHi), 100.0 * st.luminance_above_one);
            ImGui::PlotHistogram("luminance", st.luminance_histogram.data(), int(st.luminance_histogram.size()), 0, over,
                                 0, top * 1.1f, ImVec2(0, 60));
        } else {
            ImGui::TextWrapped("histogram: with --accum half or float, or --exposure auto");
        }
    }
    if (ImGui::CollapsingHeader("options (the render flags)")) {
        ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);  // the other half: the name
        for (const RenderOption& o : render_options()) {
            option_widget(st, o);
            if (!o.help.empty() && ImGui::IsItemHovered()) {  // the table's help, as --help prints it
                ImGui::BeginTooltip();
                ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30);
                ImGui::TextUnformatted(o.help.c_str());
                ImGui::PopTextWrapPos();
                ImGui::EndTooltip();
            }
        }
        ImGui::PopItemWidth();
        if (!st.option_error.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
            ImGui::TextWrapped("%s", st.option_error.c_str());
            ImGui::PopStyleColor();
        }
    }

    ImGui::End();
    (void)frame_scene;
}

void draw_scissor_overlay(const ViewerState& st, const DeferredShader& ds, const Scene& frame_scene, int w, int h) {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const ShaderOptions& o = ds.options();
    for (const LightRect& lr : light_scissor_rects(frame_scene, frame_scene.camera.view(), ds.proj_matrix(frame_scene.camera), w, h, o.scissor,
                                                   o.skip.empty_lights)) {
        const glm::vec3 c = glm::clamp(frame_scene.lights[lr.light].color, glm::vec3(0.25f), glm::vec3(1));
        const ImU32 col = IM_COL32(int(c.r * 255), int(c.g * 255), int(c.b * 255), 220);
        // GL window pixels (origin bottom-left) to ImGui's (origin top-left).
        dl->AddRect(ImVec2(float(lr.rect.x0), float(h - lr.rect.y1)), ImVec2(float(lr.rect.x1), float(h - lr.rect.y0)), col);
    }
    (void)st;
}

}  // namespace dsr
