#include "analysis/hdr_measure.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <sstream>

#include "analysis/bench_scenes.h"
#include "deferred/deferred_shader.h"
#include "deferred/paths.h"
#include "dsr_clock.h"
#include "gl/readback.h"
#include "platform/resources.h"

namespace dsr::hdr {

Scene bright_sphere_scene() {
    Scene s;
    s.camera.pos = {0, 1.5f, 5};
    s.camera.target = {0, 0.6f, 0};
    s.ambient = glm::vec3(0.05f);
    s.background = {0, 0, 0};
    Material white;
    white.name = "white";
    white.diffuse = glm::vec3(0.8f);
    white.specular = glm::vec3(0.5f);
    white.shininess = 32;
    Material grey;
    grey.name = "grey";
    grey.diffuse = glm::vec3(0.5f);
    grey.specular = glm::vec3(0);
    s.materials = {white, grey};
    add_plane(s, 10, {0, 0, 0}, 1);
    add_sphere(s, 1.0f, {0, 1, 0}, 0);
    s.lights.push_back({{1.5f, 3, 2.5f}, {4, 4, 4}, 8.0f});
    return s;
}

Scene with_lights_scaled(Scene s, float k) {
    for (Light& l : s.lights) l.color *= k;
    return s;
}

double share_above(const Image& img, float limit) {
    const size_t n = size_t(img.width) * size_t(img.height);
    if (n == 0) return 0;
    size_t over = 0;
    for (size_t i = 0; i < n; ++i) {
        const float* p = &img.rgba[4 * i];
        over += p[0] > limit || p[1] > limit || p[2] > limit;
    }
    return double(over) / double(n);
}

std::vector<Case> default_cases() {
    const Scene def = load_scene(resource_dir("data") + "/default.scene");
    return {{"bright sphere (one light 4 4 4)", bright_sphere_scene()},
            {"default scene, lights x4", with_lights_scaled(def, 4)},
            {"256 lights x4", with_lights_scaled(with_generated_lights(def, 256), 4)}};
}

std::vector<Result> measure(const Caps& caps, const std::string& shader_dir, const std::vector<Case>& cases, int size,
                            int frames, const std::function<void(const std::string&)>& say) {
    struct Config {
        AccumFormat accum;
        ToneMap tonemap;
    };
    const Config configs[] = {{AccumFormat::rgba8, ToneMap::none},   {AccumFormat::half, ToneMap::none},
                              {AccumFormat::float32, ToneMap::none}, {AccumFormat::half, ToneMap::reinhard},
                              {AccumFormat::half, ToneMap::aces}};
    for (AccumFormat a : {AccumFormat::half, AccumFormat::float32}) {
        const std::string missing = accum_format_missing(caps, caps.fbo, a);
        if (!missing.empty()) say(std::string("hdr: --accum ") + accum_format_name(a) + " left out: " + missing);
    }
    std::vector<Result> out;
    for (const Case& c : cases) {
        // Every configuration built first, then the timed frames interleaved (one frame of each a
        // round), so load from elsewhere on the machine spreads over all of them, as the bench does.
        std::vector<std::unique_ptr<DeferredShader>> shaders;
        std::vector<Config> ran;
        for (const Config& k : configs) {
            if (!accum_format_ok(caps, caps.fbo, k.accum)) continue;
            ShaderOptions o;
            o.hdr.accum = k.accum;
            o.hdr.tonemap = k.tonemap;
            shaders.push_back(std::make_unique<DeferredShader>(caps, size, size, o, shader_dir));
            shaders.back()->set_scene(c.scene);
            shaders.back()->render(c.scene, size, size);  // warm-up
            ran.push_back(k);
        }
        std::vector<std::vector<double>> ms(shaders.size());
        for (int f = 0; f < frames; ++f)
            for (size_t i = 0; i < shaders.size(); ++i) ms[i].push_back(shaders[i]->render(c.scene, size, size).ms.frame);
        for (size_t i = 0; i < shaders.size(); ++i) {
            DeferredShader& ds = *shaders[i];
            ds.render(c.scene, size, size);  // the frame whose buffers are read
            Result r;
            r.scene = c.name;
            r.accum = ran[i].accum;
            r.tonemap = ran[i].tonemap;
            r.ms_median = median(ms[i]);
            r.exposure_scale = ds.exposure_scale();
            const Image accum = ds.read_pbuffer(0);
            for (size_t k = 0; k < accum.rgba.size(); ++k)
                if (k % 4 != 3) r.accum_max = std::max(r.accum_max, double(accum.rgba[k]));
            if (r.tonemap == ToneMap::none)  // P-buffer 0: 255 in RGBA8, above 1 in float
                r.clipped = share_above(accum, r.accum == AccumFormat::rgba8 ? 254.5f / 255.0f : 1.0f);
            else
                r.clipped = share_above(read_pixels(size, size), 254.5f / 255.0f);
            out.push_back(r);
            char line[256];
            std::snprintf(line, sizeof line, "hdr: %s, %s, %s: %.2f%% clipped, %.2f ms", c.name.c_str(),
                          accum_format_name(r.accum), tone_map_name(r.tonemap), 100 * r.clipped, r.ms_median);
            say(line);
        }
    }
    return out;
}

std::string table(const std::vector<Result>& rs) {
    std::ostringstream o;
    o << "| scene | accum | tonemap | clipped pixels | P-buffer 0 max | frame ms (median) |\n"
         "| --- | --- | --- | --- | --- | --- |\n";
    for (const Result& r : rs) {
        char line[320];
        std::snprintf(line, sizeof line, "| %s | %s | %s | %.2f%% | %.2f | %.2f |\n", r.scene.c_str(),
                      accum_format_name(r.accum), tone_map_name(r.tonemap), 100 * r.clipped, r.accum_max, r.ms_median);
        o << line;
    }
    return o.str();
}

}  // namespace dsr::hdr
