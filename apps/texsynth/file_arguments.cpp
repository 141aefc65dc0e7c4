// Checks of the files a subcommand reads and writes, before it does any work.
#include <filesystem>
#include <vector>

#include "cli_common.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"

namespace texsynth::cli {
namespace fs = std::filesystem;

namespace {

enum class Role { Output, Input };
std::vector<std::pair<const CLI::Option*, Role>>& marked() {
  static std::vector<std::pair<const CLI::Option*, Role>> options;
  return options;
}

// The option as the user typed it: "--output", "-o" or a positional's name ("EXEMPLAR").
std::string flagName(const CLI::Option& option) {
  if (!option.get_lnames().empty()) return "--" + option.get_lnames().front();
  if (!option.get_snames().empty()) return "-" + option.get_snames().front();
  return option.get_name(true);
}

struct FileArgument {
  std::string path, flag;
  fs::path identity;  // absolute, symbolic links resolved where they exist
};

bool sameFile(const FileArgument& a, const FileArgument& b) {
  std::error_code ec;
  if (a.identity == b.identity) return true;
  return fs::exists(a.path, ec) && fs::exists(b.path, ec) && fs::equivalent(a.path, b.path, ec);
}

}  // namespace

CLI::Option* outputFiles(CLI::Option* option) {
  marked().push_back({option, Role::Output});
  return option;
}

CLI::Option* inputFiles(CLI::Option* option) {
  marked().push_back({option, Role::Input});
  return option;
}

void checkFileArguments(const CLI::App& subcommand) {
  std::vector<FileArgument> outputs, inputs;
  for (const CLI::Option* option : subcommand.get_options()) {
    for (const auto& [markedOption, role] : marked()) {
      if (markedOption != option) continue;
      for (const std::string& path : option->results()) {
        if (path.empty()) continue;
        std::error_code ec;
        fs::path identity = fs::weakly_canonical(fs::absolute(path, ec), ec);
        (role == Role::Output ? outputs : inputs).push_back({path, flagName(*option), identity});
      }
    }
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j)
      if (sameFile(outputs[i], outputs[j]))
        throw ParameterError(outputs[i].flag, "'" + outputs[i].path + "' is written twice (also by " + outputs[j].flag +
                                                  "); give each output its own file");
    for (const FileArgument& input : inputs)
      if (sameFile(outputs[i], input))
        throw ParameterError(outputs[i].flag, "'" + outputs[i].path + "' is also an input (" + input.flag +
                                                  "); refusing to overwrite it, give another output name");
    checkWritableDestination(outputs[i].path);
  }
}

}  // namespace texsynth::cli
