// The `dsr` subcommands; each returns the process exit status.
#pragma once
#include <string>
#include <vector>

namespace dsr {

int cmd_render(const std::vector<std::string>& args);
int cmd_info(const std::vector<std::string>& args);
int cmd_figures(const std::vector<std::string>& args);
int cmd_gen_textures(const std::vector<std::string>& args);
int cmd_gen_model(const std::vector<std::string>& args);
int cmd_stress(const std::vector<std::string>& args);
int cmd_bench(const std::vector<std::string>& args);
int cmd_hdr(const std::vector<std::string>& args);
int cmd_compare(const std::vector<std::string>& args);
int cmd_view(const std::vector<std::string>& args);  // runs dsr_view beside dsr

}  // namespace dsr
