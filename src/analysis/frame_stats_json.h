// The one JSON form of a frame's stats (deferred/frame_stats.h): `dsr render --stats` writes it at
// the top level of its file, the bench's rows under `frame` (docs/stats.md: the schema). Each
// part has its own function; frame_stats_json puts them together under the keys the files have
// always had.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "deferred/frame_stats.h"

namespace dsr {

nlohmann::ordered_json to_json(const LightCounts& c);  // lights_total, ..., lights_as_quads
nlohmann::ordered_json to_json(const TileStats& t);    // the `tiles` object's counts and times
nlohmann::ordered_json to_json(const AutoStats& a);    // the `auto` object
nlohmann::ordered_json to_json(const ShadowCounts& s); // shadow_maps, shadow_triangles, shadow_atlas_texels
nlohmann::ordered_json to_json(const ForwardCounts& f);// light_markers, transparent_objects, transparent_passes
nlohmann::ordered_json to_json(const PassesRun& p);    // the `passes` object
nlohmann::ordered_json to_json(const StageTimes& t);   // the `ms` object

// Every part: the light counts, forward and shadow counts flat; `passes`; `tiles` where
// tiles.on, `auto` where auto_geometry.on (else absent); `timing` and `ms`.
nlohmann::ordered_json frame_stats_json(const FrameStats& s);

// The frame `--stats` reports: the counted frame's counts with the timed frames' medians for its
// times (their queries around every light draw slow the counted frame): ms, the tiles' depth and
// plan ms, the tiles' GPU ms over the frames that measured them (-1 where none did), auto's
// prediction.
FrameStats reported_frame(const std::vector<FrameStats>& timed, const FrameStats& counted);

}  // namespace dsr
