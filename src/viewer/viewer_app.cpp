// The viewer's loop: GLFW window (platform/glfw_context), the deferred shader drawing into its
// back buffer, the panel on top (viewer_panel.cpp), input, resize, screenshots and --script.
// A screenshot is read back after the deferred image and before the panel is drawn, so it is
// exactly what `dsr render` writes for the same options, camera and size; a script's
// `screenshot FILE panel` is read back after the panel, before the buffers swap: the window as shown.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "analysis/ideal_fragments.h"
#include "analysis/number_format.h"
#include "dsr_clock.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/program.h"
#include "gl/readback.h"
#include "gl/state.h"
#include "platform/glfw_context.h"
#include "platform/resources.h"
#include "scene/framing.h"
#include "scene/output_set.h"
#include "viewer/script.h"
#include "viewer/viewer.h"
#include "viewer/luminance_histogram.h"
#include "viewer/viewer_state.h"

namespace dsr {

namespace {

class Viewer {
public:
    explicit Viewer(const ViewerConfig& cfg);
    ~Viewer();
    int run(const Script* script);

private:
    void rebuild();
    bool apply_option(const RenderOption& o, const std::string& value);
    // with_panel: the screenshot is taken with the panel and overlay drawn (script: screenshot FILE panel).
    bool frame(const std::string* screenshot, bool with_panel = false);
    void resize_window(int w, int h, const std::string& where);
    void update_camera(float dt);
    void on_key(int key, int mods);
    void on_scroll(double dy);
    int fb_width() const { return minimised_ ? 0 : ctx_->width(); }
    int fb_height() const { return minimised_ ? 0 : ctx_->height(); }
    void screenshot(const std::string& path, int w, int h);
    void print_summary() const;

    ViewerConfig cfg_;
    Scene scene_;        // as loaded
    Scene frame_scene_;  // this frame's camera and (animated) lights
    Camera camera_;      // where the camera is
    std::unique_ptr<GlfwContext> ctx_;
    std::unique_ptr<DeferredShader> ds_;
    ViewerState st_;
    bool minimised_ = false;   // `size 0 0`: treated as a 0x0 framebuffer whatever the X server does
    bool quit_ = false;
    std::string pending_shot_;  // F12
    OutputSet shots_{""};        // the script's screenshots, renamed together when it ends
    std::map<std::string, std::string> shot_flags_;  // script screenshot path -> "FILE:LINE: screenshot"
    std::vector<std::string> shot_lines_;            // their "wrote" lines, printed once renamed
    double start_ = 0, last_time_ = 0, anim_angle_ = 0, ideal_time_ = -1e9;
    double last_x_ = 0, last_y_ = 0;
    bool dragging_ = false, orbiting_ = false;  // right-drag looks, left-drag orbits the scene's target
    std::vector<double> frame_ms_, loop_ms_;  // every rendered frame, for the summary
    long long programs_after_build_ = 0;
};

Viewer::Viewer(const ViewerConfig& cfg) : cfg_(cfg) {
    const std::string path = cfg.scene_path.empty() ? resource_dir("data") + "/default.scene" : cfg.scene_path;
    scene_ = load_scene(path, cfg.load);  // input errors before any window opens
    for (size_t i = 0; i < scene_.inputs.size(); ++i)
        shots_.add_input(scene_.inputs[i], i == 0 ? "the scene file" : "a file the scene reads,");
    if (cfg.lights) scene_ = bench_scene(scene_, *cfg.lights);  // as `render --lights` (bench_scenes.h)
    cfg_.scene_path = path;
    camera_ = scene_.camera;
    st_.options = cfg.options;
    // The viewer shows the switches as they are: the scene's `post` line where no flag said.
    if (st_.options.bloom < 0) st_.options.bloom = scene_.post_bloom;
    if (st_.options.aa < 0) st_.options.aa = scene_.post_aa;
    st_.fly = FlyCamera::from(camera_);

    ctx_ = std::make_unique<GlfwContext>(cfg.width, cfg.height, "dsr view " + path);
    load_gl_entry_points(*ctx_);
    gl_state().reset();
    st_.caps = probe_caps(split_caps(cfg.caps_list));
    st_.renderer = st_.caps.renderer + ", GL " + st_.caps.version;

    glfwSetWindowUserPointer(ctx_->window(), this);
    // Installed before ImGui's, which chains to them.
    glfwSetKeyCallback(ctx_->window(), [](GLFWwindow* w, int key, int, int action, int mods) {
        auto* v = static_cast<Viewer*>(glfwGetWindowUserPointer(w));
        if (action == GLFW_PRESS && !(ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard)) v->on_key(key, mods);
    });
    glfwSetScrollCallback(ctx_->window(), [](GLFWwindow* w, double, double dy) {
        auto* v = static_cast<Viewer*>(glfwGetWindowUserPointer(w));
        if (!(ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse)) v->on_scroll(dy);
    });
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(ctx_->window(), true);
    ImGui_ImplOpenGL2_Init();
    gl_state().reset();

    rebuild();
    std::printf("dsr view: %s, %s, %dx%d (F1: panel, Esc: quit; dsr view --help lists the keys)\n", path.c_str(),
                st_.renderer.c_str(), ctx_->width(), ctx_->height());
    std::fflush(stdout);
    start_ = last_time_ = now_ms() / 1000.0;
}

Viewer::~Viewer() {
    ds_.reset();
    if (ImGui::GetCurrentContext()) {
        ImGui_ImplOpenGL2_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
}

// A new DeferredShader for the options (programs and formats may differ); resizes never come here.
void Viewer::rebuild() {
    int w = fb_width(), h = fb_height();
    if (w <= 0 || h <= 0) w = cfg_.width, h = cfg_.height;
    ds_.reset();
    ds_ = std::make_unique<DeferredShader>(st_.caps, w, h, st_.options.resolved(scene_), resource_dir("glsl120"));
    ds_->set_scene(scene_);
    ++st_.builds;
    programs_after_build_ = Program::built();
}

// Sets an option (panel, key or script); false with st_.option_error when refused.
bool Viewer::apply_option(const RenderOption& o, const std::string& value) {
    const RenderOptions before = st_.options;
    const std::string err = set_render_option(st_.options, o, value);
    if (!err.empty()) {
        st_.option_error = o.name + ": " + err;
        return false;
    }
    // The bloom and ssao views need their pass built (RenderOptions::resolved).
    const bool bloom_view_change = (before.view == View::bloom) != (st_.options.view == View::bloom) ||
                                   (before.view == View::ssao) != (st_.options.view == View::ssao);
    if (!o.rebuild && !bloom_view_change) return true;
    try {
        rebuild();
    } catch (const Error& e) {  // e.g. a depth path the GL cannot take
        st_.options = before;
        st_.option_error = o.name + " " + value + ": " + e.what();
        rebuild();
        return false;
    }
    st_.option_error.clear();
    return true;
}

void Viewer::resize_window(int w, int h, const std::string& where) {
    if (w == 0) {
        // A 0x0 framebuffer, as a minimised window has. Without a window manager (Xvfb) the
        // iconify request does nothing, so the viewer treats the window as 0x0 itself.
        minimised_ = true;
        glfwIconifyWindow(ctx_->window());
        glfwPollEvents();
        return;
    }
    if (minimised_) {
        glfwRestoreWindow(ctx_->window());
        minimised_ = false;
    }
    glfwSetWindowSize(ctx_->window(), w, h);
    const double t0 = now_ms();
    while (ctx_->width() != w || ctx_->height() != h) {
        glfwWaitEventsTimeout(0.02);
        if (now_ms() - t0 > 3000)
            throw Error(where + "size " + std::to_string(w) + " " + std::to_string(h) + ": the window is still " +
                        std::to_string(ctx_->width()) + "x" + std::to_string(ctx_->height()) +
                        " after 3 s (larger than the screen?)");
    }
}

// A script's screenshot goes to a temporary file, renamed with the others when the script's
// run ends (scene/output_set.h: a failure leaves none); F12's is written at once.
void Viewer::screenshot(const std::string& path, int w, int h) {
    const Image img = opaque(read_pixels(w, h));
    const FrameStats& s = st_.last;
    // "panel on": drawn over the window after this read-back, unless the script asked for it.
    char line[512];
    std::snprintf(line, sizeof line, " (%dx%d, view %s, scissor %s, panel %s, %d/%d lights drawn, scissor_pixels %lld)",
                  w, h, view_name(st_.options.view), st_.options.shader.scissor ? "on" : "off",
                  st_.panel ? "on" : "off", s.lights.drawn, s.lights.total, s.lights.scissor_pixels);
    auto flag = shot_flags_.find(path);
    if (flag == shot_flags_.end()) {
        write_image(path, img);
        std::printf("wrote %s%s\n", path.c_str(), line);
        std::fflush(stdout);
        return;
    }
    shots_.put_image(flag->second, path, img);
    shot_lines_.push_back("wrote " + path + line);
}

// One frame; false (after a short wait, so a minimised window does not spin) when there is
// nothing to draw into.
bool Viewer::frame(const std::string* shot, bool with_panel) {
    glfwPollEvents();
    const double now = now_ms() / 1000.0;
    const float dt = float(std::min(0.25, now - last_time_));
    last_time_ = now;
    const int w = fb_width(), h = fb_height();
    if (w <= 0 || h <= 0) {
        glfwWaitEventsTimeout(0.05);
        return false;
    }
    const double t0 = now_ms();
    if (w != ds_->width() || h != ds_->height()) {
        ds_->resize(w, h);  // buffers only; no shader is built (checked in the summary line)
        ++st_.resizes;
    }
    update_camera(dt);
    frame_scene_ = scene_;
    frame_scene_.camera = camera_;
    if (st_.animate) anim_angle_ += 0.5 * dt;
    if (anim_angle_ != 0) {  // lights turn about the vertical through the scene camera's target
        const glm::vec3 pivot = scene_.camera.target;
        const glm::mat4 r = glm::rotate(glm::mat4(1), float(anim_angle_), glm::vec3(0, 1, 0));
        for (Light& l : frame_scene_.lights) l.pos = pivot + glm::vec3(r * glm::vec4(l.pos - pivot, 0));
    }
    st_.last = ds_->render(frame_scene_, w, h);
    if (st_.options.view != View::final) {
        try {
            ds_->draw_view(st_.options.view, frame_scene_.camera, w, h);
        } catch (const Error&) {
            ds_->final_stage(w, h);  // a view the frame has nothing for (shadow-map, no shadowed light visible)
        }
    }
    check_gl("viewer frame");
    if (shot && !with_panel) screenshot(*shot, w, h);
    if (!pending_shot_.empty()) {
        screenshot(pending_shot_, w, h);
        pending_shot_.clear();
    }
    // The ideal count (the bench's and `render --stats`' one count, from the depth texture's
    // codes in double), once a second while the panel shows it.
    if (st_.panel && ds_->paths().depth_path == DepthPath::texture && now - ideal_time_ > 1.0) {
        ideal_time_ = now;
        st_.ideal = ideal_count_from_depth_codes(ds_->read_gbuffer_depth_codes(), w, h, frame_scene_.camera,
                                                 frame_scene_.lights);
    } else if (ds_->paths().depth_path != DepthPath::texture) {
        st_.ideal.reset();
    }

    // P-buffer 0's luminance for the panel's histogram and the exposure applied (docs/hdr.md).
    st_.exposure_scale = ds_->exposure_scale();
    if (st_.panel) {
        const LuminanceHistogram lh = luminance_histogram(ds_->reduce_luminance(), 48, ViewerState::kHistogramLo,
                                                          ViewerState::kHistogramHi);
        st_.luminance_histogram = lh.bins;
        st_.luminance_above_one = lh.above_one;
    }
    // Dear ImGui's GL 2 backend draws by fixed function and binds no program of its own: the last
    // pass may have left one (the tone-mapping final pass, the luminance reduction).
    gl_state().apply(fixed_function_2d());
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (st_.overlay) draw_scissor_overlay(st_, *ds_, frame_scene_, w, h);
    if (st_.panel) draw_panel(st_, *ds_, frame_scene_, w, h);
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    gl_state().reset();  // foreign GL code ran (the viewer's panel: Dear ImGui)
    if (shot && with_panel) screenshot(*shot, w, h);
    ctx_->swap();

    const auto pending = std::move(st_.pending);  // the panel's changes, now that it is drawn
    st_.pending.clear();
    for (const auto& [o, value] : pending) apply_option(*o, value);
    st_.loop_ms = now_ms() - t0;
    frame_ms_.push_back(st_.last.ms.frame);
    loop_ms_.push_back(st_.loop_ms);
    st_.history.push_back({now - start_, st_.last.ms.frame, st_.last.ms.lights});
    while (!st_.history.empty() && st_.history.front().t < now - start_ - 5.0) st_.history.pop_front();
    return true;
}

void Viewer::update_camera(float dt) {
    GLFWwindow* win = ctx_->window();
    const bool mouse_free = !ImGui::GetIO().WantCaptureMouse;
    double x, y;
    glfwGetCursorPos(win, &x, &y);
    if (glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && (dragging_ || mouse_free)) {
        if (dragging_) {
            st_.fly.look(float(-(x - last_x_) * 0.004), float(-(y - last_y_) * 0.004));
            camera_ = st_.fly.apply(camera_);  // keeps camera_'s fov, near and far
        }
        dragging_ = true;
    } else if (glfwGetMouseButton(win, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS && (orbiting_ || mouse_free)) {
        if (orbiting_) {
            st_.fly.orbit(scene_.camera.target, float(-(x - last_x_) * 0.006), float(-(y - last_y_) * 0.006));
            camera_ = st_.fly.apply(camera_);
        }
        orbiting_ = true;
    } else {
        dragging_ = orbiting_ = false;
    }
    last_x_ = x, last_y_ = y;
    if (ImGui::GetIO().WantCaptureKeyboard) return;
    glm::vec3 d(0);
    auto down = [&](int k) { return glfwGetKey(win, k) == GLFW_PRESS; };
    if (down(GLFW_KEY_W)) d.z += 1;
    if (down(GLFW_KEY_S)) d.z -= 1;
    if (down(GLFW_KEY_D)) d.x += 1;
    if (down(GLFW_KEY_A)) d.x -= 1;
    if (down(GLFW_KEY_E)) d.y += 1;
    if (down(GLFW_KEY_Q)) d.y -= 1;
    if (d != glm::vec3(0)) {
        const bool fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
        st_.fly.move(d, dt, fast ? 4.0f : 1.0f);
        camera_ = st_.fly.apply(camera_);  // keeps camera_'s fov, near and far
    }
}

void Viewer::on_scroll(double dy) { st_.fly.speed *= float(std::pow(1.25, dy)); }

void Viewer::on_key(int key, int mods) {
    auto toggle = [&](const char* name) {
        const RenderOption* o = find_render_option(name);
        apply_option(*o, o->get(st_.options) == "on" ? "off" : "on");
    };
    switch (key) {
        case GLFW_KEY_ESCAPE: quit_ = true; break;
        case GLFW_KEY_F1:
        case GLFW_KEY_TAB: st_.panel = !st_.panel; break;
        case GLFW_KEY_R:
            camera_ = scene_.camera;
            st_.fly = FlyCamera::from(camera_);
            break;
        case GLFW_KEY_F:  // frame the scene from where the camera looks (scene/framing.h)
            camera_ = reframe(scene_, camera_, fb_height() > 0 ? float(fb_width()) / float(fb_height()) : 1.0f);
            st_.fly = FlyCamera::from(camera_);
            break;
        case GLFW_KEY_L: st_.animate = !st_.animate; break;
        case GLFW_KEY_O: st_.overlay = !st_.overlay; break;
        case GLFW_KEY_C: toggle("scissor"); break;
        case GLFW_KEY_B: toggle("bloom"); break;
        case GLFW_KEY_N: toggle("aa"); break;
        case GLFW_KEY_P:
            apply_option(*find_render_option("depth"), ds_->paths().depth_path == DepthPath::packed ? "texture" : "packed");
            break;
        case GLFW_KEY_V: {
            const auto& names = view_names();
            const int n = int(names.size()), step = (mods & GLFW_MOD_SHIFT) ? n - 1 : 1;
            apply_option(*find_render_option("view"), names[(int(st_.options.view) + step) % n]);
            break;
        }
        case GLFW_KEY_F12: {
            char name[64];
            const std::time_t t = std::time(nullptr);
            std::strftime(name, sizeof name, "dsr_view_%Y%m%d_%H%M%S.png", std::localtime(&t));
            pending_shot_ = name;
            break;
        }
        default:
            if (key >= GLFW_KEY_1 && key < GLFW_KEY_1 + int(view_names().size()))
                apply_option(*find_render_option("view"), view_names()[key - GLFW_KEY_1]);
    }
}

void Viewer::print_summary() const {
    std::printf("dsr view: %zu frames, frame %.2f ms median (renderer), loop %.2f ms median (with panel and swap); "
                "%d resizes, deferred shader built %d time%s, %lld programs built since\n",
                frame_ms_.size(), median(frame_ms_), median(loop_ms_), st_.resizes, st_.builds, st_.builds == 1 ? "" : "s",
                Program::built() - programs_after_build_);
    std::fflush(stdout);
}

int Viewer::run(const Script* script) {
    if (script) {
        // Every screenshot path is checked against the inputs before the first frame.
        shots_.add_input(script->path, "the script");
        for (const ScriptCommand& c : script->commands)
            if (c.kind == ScriptCommand::screenshot && !shot_flags_.count(c.value)) {
                shots_.add(script->where(c) + "screenshot", c.value);
                shot_flags_[c.value] = script->where(c) + "screenshot";
            }
        for (const ScriptCommand& c : script->commands) {
            const std::string where = script->where(c);
            switch (c.kind) {
                case ScriptCommand::size: resize_window(c.w, c.h, where); break;
                case ScriptCommand::camera:
                    camera_ = scene_.camera;
                    camera_.pos = c.pos, camera_.target = c.target, camera_.up = c.up;
                    st_.fly = FlyCamera::from(camera_);
                    break;
                case ScriptCommand::set:
                    if (const RenderOption* o = find_render_option(c.name)) {
                        if (!apply_option(*o, c.value)) throw Error(where + "set " + st_.option_error);
                    } else {  // the viewer's own: panel, overlay, animate
                        bool& b = c.name == "panel" ? st_.panel : c.name == "overlay" ? st_.overlay : st_.animate;
                        b = c.value == "on";
                    }
                    break;
                case ScriptCommand::frames:
                    for (int i = 0; i < c.count && !quit_ && !glfwWindowShouldClose(ctx_->window()); ++i) frame(nullptr);
                    break;
                case ScriptCommand::screenshot:
                    if (fb_width() <= 0 || fb_height() <= 0)
                        throw Error(where + "screenshot: the window is minimised (0x0): nothing to capture");
                    try {
                        frame(&c.value, c.with_panel);
                    } catch (const Error& e) {
                        const std::string what = e.what();  // add() named the line already
                        throw Error(what.rfind(where, 0) == 0 ? what : where + "screenshot: " + what);
                    }
                    break;
                case ScriptCommand::quit: quit_ = true; break;
                case ScriptCommand::wait: break;  // the last command: the loop below goes on
            }
            if (quit_ || glfwWindowShouldClose(ctx_->window())) break;
        }
        // The script's screenshots are whole now: renamed into place before the window goes on, so
        // a `wait` script leaves them for a person or a tool that waits for the file.
        shots_.commit();
        if (!script->waits()) quit_ = true;  // a script ends when it ends (script.h)
    }
    while (!quit_ && !glfwWindowShouldClose(ctx_->window())) frame(nullptr);
    shots_.commit();
    for (const std::string& l : shot_lines_) std::printf("%s\n", l.c_str());
    print_summary();
    return 0;
}

}  // namespace

int run_viewer(const ViewerConfig& config) {
    // The whole script is read and checked before the window opens: a bad line runs nothing.
    std::unique_ptr<Script> script;
    if (!config.script_path.empty()) script = std::make_unique<Script>(load_script(config.script_path));
    Viewer v(config);
    return v.run(script.get());
}

}  // namespace dsr
