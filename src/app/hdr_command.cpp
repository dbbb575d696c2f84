// `dsr hdr`: analysis/hdr_measure.h's table on stdout, progress on stderr.
#include <cstdio>

#include "analysis/hdr_measure.h"
#include "app/command_table.h"
#include "app/commands.h"
#include "app/stage.h"
#include "gl/caps.h"
#include "platform/context.h"
#include "platform/resources.h"

namespace dsr {

int cmd_hdr(const std::vector<std::string>& argv) {
    HdrSettings flags;
    parse_command_line(hdr_command(flags), argv);
    const Stage stage("measuring light beyond 1.0");
    auto ctx = create_context(context_desc(flags.context, flags.size, flags.size));
    const Caps caps = probe_caps(split_caps(caps_with_environment(flags.caps)));
    const auto results = hdr::measure(caps, resource_dir("glsl120"), hdr::default_cases(), flags.size, flags.frames,
                                      [](const std::string& s) { std::fprintf(stderr, "%s\n", s.c_str()); });
    std::printf("%s (%s), %dx%d, median of %d frames\n\n%s", caps.renderer.c_str(), ctx->description().c_str(),
                flags.size, flags.size, flags.frames, hdr::table(results).c_str());
    return 0;
}

}  // namespace dsr
