// Each subcommand lives in its own file (cmd_<name>.cpp) and registers itself here.
// A command's callback throws InputError for bad input; main() turns that into exit code 1.
#pragma once

#include <CLI/CLI.hpp>

namespace rastrace {

void add_version_command(CLI::App& app);
void add_replay_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_merge_command(CLI::App& app);
void add_trace_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_reorder_command(CLI::App& app);
void add_vcache_command(CLI::App& app);
void add_meshlets_command(CLI::App& app);
void add_vipm_command(CLI::App& app);
void add_adjacency_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_texsweep_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_reproduce_command(CLI::App& app);
void add_overdraw_command(CLI::App& app);

}  // namespace rastrace
