// `rastrace version`: the tool version and the versions of the libraries it measures against.
#include <iostream>

#include "apps/commands.h"

namespace rastrace {

void add_version_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("version", "Print the rastrace version");
  command->footer("Example:\n  rastrace version");
  command->callback([] { std::cout << "rastrace " RASTRACE_VERSION "\n"; });
}

}  // namespace rastrace
