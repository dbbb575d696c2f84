// Hostile command lines: names and values with newlines, control characters and bytes that are
// not UTF-8, empty values, flags with nothing after them. Still one line naming what was wrong,
// for every command.
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

std::vector<Case> cases() {
    std::vector<Case> c;
    auto scene = [](D d) { write(d, "a.scene", scene_text()); };
    c.push_back({"unknown_command_with_newline", nullptr, "$'ren\\nder'", "dsr: unknown command 'ren?der'", 2});
    c.push_back({"scene_name_with_newline", nullptr, "render $'a\\nb.scene' -o out.png", "cannot open scene file a b.scene: No such file or directory"});
    c.push_back({"scene_name_not_utf8", nullptr, "render $'\\xff\\xfe.scene' -o out.png", "cannot open scene file ??.scene: No such file or directory"});
    c.push_back({"flag_value_with_newline", scene, "render a.scene --depth $'tex\\nture' -o out.png", "dsr render: --depth: expected auto|texture|packed|position16|position32, got 'tex?ture'"});
    c.push_back({"flag_value_escape", scene, "render a.scene --view $'\\x1b[2J' -o out.png", "dsr render: --view: expected"});
    c.push_back({"size_missing", scene, "render a.scene --size", "dsr render: --size: expected a value, got nothing"});
    c.push_back({"size_empty", scene, "render a.scene --size ''", "dsr render: --size: expected a value, got ''"});
    c.push_back({"caps_empty", scene, "render a.scene --caps '' -o out.png", "dsr render: --caps: expected a value, got ''"});
    c.push_back({"context_empty", scene, "render a.scene --context '' -o out.png", "dsr render: --context: expected a value, got ''"});
    c.push_back({"two_scenes", scene, "render a.scene a.scene -o out.png", "dsr render: expected one scene file, got also 'a.scene'"});
    c.push_back({"compare_one_file", nullptr, "compare a.png", "dsr compare: expected two image files, got 1"});
    c.push_back({"compare_threshold_empty", nullptr, "compare a.png b.png --threshold ''", "dsr compare: --threshold: expected a value, got ''"});
    c.push_back({"info_caps_empty", nullptr, "info --caps ''", "dsr info: --caps: expected a value, got ''"});
    c.push_back({"stress_only_empty", nullptr, "stress --quick --only ''", "dsr stress: --only: expected a value, got ''"});
    c.push_back({"bench_lights_empty", scene, "bench a.scene --quick --lights ''", "dsr bench: --lights: expected a value, got ''"});
    c.push_back({"view_size_empty", scene, "view a.scene --size ''", "dsr view: --size: expected a value, got ''"});
    return c;
}

INSTANTIATE_TEST_SUITE_P(Cli, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
