// `dsr figures`: the tutorial's raster figures (4, 6, 8, 9, 10, 11) from the default scene,
// each a plain PNG; docs/figures.md sets them beside the captions.
#include <stdlib.h>

#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <functional>

#include "app/command_table.h"
#include "app/commands.h"
#include "dsr_error.h"
#include "app/files.h"
#include "app/stage.h"
#include "deferred/deferred_shader.h"
#include "gl/caps.h"
#include "gl/readback.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/generated_model.h"
#include "scene/scene.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

// A square close-up, magnified with nearest neighbour so single pixels (and aliasing)
// stay visible. (x0, y0) is the top-left corner in top-down pixel coordinates.
Image closeup(const Image& src, int x0, int y0, int size, int zoom) {
    Image out;
    out.width = out.height = size * zoom;
    out.rgba.resize(size_t(out.width) * out.height * 4);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            int sx = x0 + x / zoom;
            int sy = src.height - 1 - (y0 + (out.height - 1 - y) / zoom);  // rows are bottom-first
            const float* p = src.at(sx, sy);
            float* q = out.at(x, y);
            for (int c = 0; c < 4; ++c) q[c] = p[c];
        }
    return out;
}

}  // namespace

int cmd_figures(const std::vector<std::string>& argv) {
    FiguresSettings flags;  // the figures command's table (app/command_table.h)
    parse_command_line(figures_command(flags), argv);
    const std::string dir = flags.dir;
    std::string scene_path = flags.scene;
    const int n = flags.size;
    const bool default_scene = scene_path.empty();
    if (default_scene) scene_path = resource_dir("data") + "/default.scene";
    Scene scene = load_scene(scene_path);
    // Every figure to a temporary file, renamed together at the end (scene/output_set.h).
    OutputSet outputs("dsr figures");
    add_scene_inputs(outputs, scene.inputs);
    if (dir == FiguresSettings{}.dir) outputs.make_dir("-o", kOutDir);  // the default's parent
    require_folder("dsr figures", "-o", dir);
    outputs.make_dir("-o", dir);
    const Stage stage("rendering the figures of " + scene_path);
    auto ctx = create_context(context_desc(flags.context, n, n));
    Caps caps = probe_caps();
    const std::string shaders = resource_dir("glsl120");
    auto save = [&](const std::string& name, const Image& img) { outputs.put_image("-o", dir + "/" + name, opaque(img)); };
    // One shader per configuration; `then` reads what it needs after one frame.
    auto frame = [&](ShaderOptions o, const std::function<void(DeferredShader&)>& then) {
        DeferredShader ds(caps, n, n, o, shaders);
        ds.set_scene(scene);
        ds.render(scene, n, n);
        then(ds);
    };
    auto view = [&](DeferredShader& ds, View v) {
        ds.draw_view(v, scene.camera, n, n);
        return read_pixels(n, n);
    };
    const int cx = n * 300 / 512, cy = n * 220 / 512, cs = n / 4;  // close-up: the red ball's rim on the floor

    // The tutorial's figures with the tutorial's light pass: one scissored quad per light (§3.4.2).
    ShaderOptions plain;
    plain.light_geometry = LightGeometry::quad;
    ShaderOptions packed = plain;
    packed.depth = DepthPath::packed;
    frame(packed, [&](DeferredShader& ds) {  // Figure 4: the G-buffer of the packed path
        save("fig4a_normal.png", view(ds, View::normal));
        save("fig4b_diffuse.png", view(ds, View::diffuse));
        save("fig4c_specular.png", view(ds, View::specular));
        save("fig4d_depth.png", view(ds, View::depth));
    });
    ShaderOptions full = plain;
    full.post.bloom = full.post.aa = true;
    frame(full, [&](DeferredShader& ds) { save("fig6_final.png", view(ds, View::final)); });
    ShaderOptions aa = plain;
    aa.post.aa = true;
    frame(aa, [&](DeferredShader& ds) {
        Image f = view(ds, View::final);
        Image b = view(ds, View::blur_factor);
        save("fig8_blur_factor.png", b);
        save("fig8_blur_factor_closeup.png", closeup(b, cx, cy, cs, 4));
        save("fig9_closeup_with_aa.png", closeup(f, cx, cy, cs, 4));
    });
    frame(plain, [&](DeferredShader& ds) {
        Image f = view(ds, View::final);
        save("fig9_closeup_without_aa.png", closeup(f, cx, cy, cs, 4));
        save("fig11_without_bloom.png", f);
        save("ssao_without.png", f);
        if (default_scene) save("shadows_without.png", f);
    });
    ShaderOptions bloom = plain;
    bloom.post.bloom = true;
    frame(bloom, [&](DeferredShader& ds) {
        save("fig11_with_bloom.png", view(ds, View::final));
        // Figure 10 step by step on the un-bloomed lighting result.
        FrameStats st;
        ds.geometry_stage(scene);
        ds.draw_lights(scene, true, st);
        ds.blur(0, 2, {1, 0}, true);
        save("fig10a_horizontal_blur.png", ds.read_pbuffer(2));
        ds.blur(0, 3, {0, 1}, true);
        save("fig10b_vertical_blur.png", ds.read_pbuffer(3));
        ds.blur(2, 3, {0, 1}, false);
        save("fig10c_composed_blur.png", ds.read_pbuffer(3));
    });
    // SSAO (docs/ssao.md, Vasilovici §5): the default options, the image with and without and the
    // blurred AO buffer the ambient pass (Listing 15, Eq. 6) is multiplied by; without it the
    // image is fig11_without_bloom, saved again as ssao_without beside them.
    ShaderOptions ssao = plain;
    ssao.ssao.on = true;
    frame(ssao, [&](DeferredShader& ds) {
        save("ssao_with.png", view(ds, View::final));
        save("ssao_buffer.png", view(ds, View::ssao));
    });
    // Shadows (docs/accuracy.md, "Shadows"): the default scene with `shadow` on each of its three
    // point lights (six faces each, the default map size, bias, slope and filter), beside the scene
    // as it is (shadows_without, saved above), and the first light's map as --view shadow-map shows
    // it; only with the default scene.
    if (default_scene) {
        Scene shadowed = scene;
        for (Light& l : shadowed.lights) l.shadow.on = true;
        ShaderOptions o = plain;
        o.shadow_lights = true;  // as RenderOptions::resolved sets it for a scene with `shadow`
        DeferredShader ds(caps, n, n, o, shaders);
        ds.set_scene(shadowed);
        ds.render(shadowed, n, n);
        save("shadows_with.png", view(ds, View::final));
        save("shadows_map.png", view(ds, View::shadow_map));
    }
    // Transparency (docs/forward.md, the tutorial's §4 answer to its "major limitation"): the panes and
    // the glass ball are left out of the G-buffer (its diffuse view shows the wall through them)
    // and blended after the lights by the forward stage, with --show-lights markers that bloom
    // makes glow; only with the default scene (its own scene file is fixed).
    if (default_scene) {
        const Scene ts = load_scene(resource_dir("data") + "/transparency.scene");
        add_scene_inputs(outputs, ts.inputs);
        ShaderOptions o = plain;
        o.post.bloom = o.post.aa = true;  // the scene's `post bloom aa`
        o.show_lights = true;
        DeferredShader ds(caps, n, n, o, shaders);
        ds.set_scene(ts);
        ds.render(ts, n, n);
        save("transparency_final.png", view(ds, View::final));
        save("transparency_diffuse.png", view(ds, View::diffuse));
    }
    // Beside Figure 6, a real model through the OBJ loader: the windmill `dsr gen-model` writes
    // (scene/generated_model.h: OBJ + MTL, map_Kd, tangent-space normal maps, map_Ks and map_Ns
    // specular maps), generated into a temporary folder and framed as `dsr render windmill.obj`
    // frames it (scene/framing.h); only with the default scene.
    if (default_scene) {
        std::string tmpl = (std::filesystem::temp_directory_path() / "dsr-figures-XXXXXX").string();
        if (!mkdtemp(tmpl.data())) throw Error("figures: cannot make a temporary folder " + tmpl);
        Scene wm;
        try {
            wm = load_scene(write_model(windmill_model(), tmpl));
        } catch (...) {
            std::filesystem::remove_all(tmpl);
            throw;
        }
        std::filesystem::remove_all(tmpl);  // the maps are in memory now
        ShaderOptions o = plain;
        o.post.aa = true;
        DeferredShader ds(caps, n, n, o, shaders);
        ds.set_scene(wm);
        ds.render(wm, n, n);
        save("windmill_final.png", view(ds, View::final));
        save("windmill_normal.png", view(ds, View::normal));
        save("windmill_specular.png", view(ds, View::specular));
    }
    // Models nobody here wrote (docs/models.md): a glTF and a textured OBJ of Debian's
    // assimp-testmodels, framed and lit as `dsr render FILE` shows them (the key light's shadow
    // on). Read in place from the package; only with the default scene.
    if (default_scene) {
        const std::string corpus = "/usr/share/assimp/models";
        const struct {
            const char* file;
            const char* out;
        } models[] = {{"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "model_engine.png"},
                      {"OBJ/spider.obj", "model_spider.png"}};
        for (const auto& m : models) {
            const std::string path = corpus + "/" + m.file;
            if (!std::filesystem::is_regular_file(path)) {
                std::printf("figures: %s left out: %s is absent (make deps installs assimp-testmodels)\n", m.out, path.c_str());
                continue;
            }
            const Scene ms = load_scene(path);
            add_scene_inputs(outputs, ms.inputs);
            RenderOptions ro;
            ShaderOptions o = ro.resolved(ms);  // the model's shadow light on
            o.light_geometry = plain.light_geometry;
            o.post.aa = true;
            DeferredShader ds(caps, n, n, o, shaders);
            ds.set_scene(ms);
            ds.render(ms, n, n);
            save(m.out, view(ds, View::final));
        }
    }
    // Light beyond 1.0 (docs/hdr.md): the default scene with its lights x4, with the tutorial's RGBA8
    // P-buffer 0 (sums clip at 1) and in half floats with each operator of the final stage; last, the
    // linear pipeline whole (sRGB colour maps decoded, ACES, sRGB output). Only with the default scene.
    if (default_scene) {
        Scene bright = scene;
        for (Light& l : bright.lights) l.color *= 4.0f;
        struct HdrFigure {
            const char* file;
            AccumFormat accum;
            ToneMap tonemap;
            bool srgb;
        };
        const HdrFigure figures[] = {{"hdr_rgba8.png", AccumFormat::rgba8, ToneMap::none, false},
                                     {"hdr_half_none.png", AccumFormat::half, ToneMap::none, false},
                                     {"hdr_half_reinhard.png", AccumFormat::half, ToneMap::reinhard, false},
                                     {"hdr_half_aces.png", AccumFormat::half, ToneMap::aces, false},
                                     {"hdr_half_aces_srgb.png", AccumFormat::half, ToneMap::aces, true}};
        for (const HdrFigure& h : figures) {
            if (!accum_format_ok(caps, caps.fbo, h.accum)) continue;  // a GL without float targets: left out
            ShaderOptions o = plain;
            o.hdr.accum = h.accum;
            o.hdr.tonemap = h.tonemap;
            o.hdr.output_srgb = o.hdr.textures_srgb = h.srgb;
            DeferredShader ds(caps, n, n, o, shaders);
            ds.set_scene(bright);
            ds.render(bright, n, n);
            save(h.file, view(ds, View::final));
        }
    }
    // glTF's metallic-roughness BRDF (docs/metal_rough.md): data/metal_rough.scene's grid of spheres,
    // metallic 0 to 1 across and roughness 0 to 1 down, in half floats, ACES and sRGB output (the
    // linear pipeline, docs/hdr.md). Only with the default scene, where a GL has float targets.
    if (default_scene && accum_format_ok(caps, caps.fbo, AccumFormat::half)) {
        const Scene mr = load_scene(resource_dir("data") + "/metal_rough.scene");
        add_scene_inputs(outputs, mr.inputs);
        RenderOptions ro;
        ShaderOptions o = ro.resolved(mr);  // the light programs' material model flag
        o.light_geometry = plain.light_geometry;
        o.hdr.accum = AccumFormat::half;
        o.hdr.tonemap = ToneMap::aces;
        o.hdr.output_srgb = true;
        DeferredShader ds(caps, n, n, o, shaders);
        ds.set_scene(mr);
        ds.render(mr, n, n);
        save("metal_rough_grid.png", view(ds, View::final));
    }
    outputs.commit();
    for (auto& w : outputs.written()) std::printf("wrote %s\n", w.c_str());
    return 0;
}

}  // namespace dsr
