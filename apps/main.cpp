// rastrace: how the order in which triangles are drawn changes GPU memory traffic.
// Exit codes: 0 success, 1 runtime error (bad input), 2 usage error.
#include <cstdio>
#include <exception>
#include <iostream>

#include "apps/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"rastrace: measures how triangle order changes GPU memory traffic"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rastrace " RASTRACE_VERSION);
  rastrace::add_version_command(app);
  rastrace::add_replay_command(app);
  rastrace::add_sweep_command(app);
  rastrace::add_merge_command(app);
  rastrace::add_trace_command(app);
  rastrace::add_info_command(app);
  rastrace::add_convert_command(app);
  rastrace::add_reorder_command(app);
  rastrace::add_vcache_command(app);
  rastrace::add_meshlets_command(app);
  rastrace::add_vipm_command(app);
  rastrace::add_adjacency_command(app);
  rastrace::add_render_command(app);
  rastrace::add_compare_command(app);
  rastrace::add_texsweep_command(app);
  rastrace::add_report_command(app);
  rastrace::add_reproduce_command(app);
  rastrace::add_overdraw_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << "rastrace: " << e.what() << "\nRun with --help for usage.\n";
    return 2;
  } catch (const rastrace::InputError& e) {
    std::cerr << "rastrace: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "rastrace: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
