// Checks of the files a subcommand reads and writes, before it does any work.
#include <filesystem>
#include <unordered_map>
#include <vector>

#include "cli_common.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/frame_pattern.h"

namespace texsynth::cli {
namespace fs = std::filesystem;

namespace {

enum class Role { Output, Input };
struct Marked {
  const CLI::Option* option;
  Role role;
  const int* frames;  // values may be frame patterns naming frames 0 .. *frames - 1; nullptr: plain files
};
std::vector<Marked>& marked() {
  static std::vector<Marked> options;
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
  std::string typed;  // the value as given: the path, or the frame pattern it comes from
  fs::path identity;  // absolute, symbolic links resolved where they exist
};

fs::path identityOf(const fs::path& path) {
  std::error_code ec;
  return fs::weakly_canonical(fs::absolute(path, ec), ec);
}

// The files one value names: itself, or each frame's file of a pattern. The directory is resolved
// once when the frame number is in the file name only, so a long animation costs no more than a
// hash per frame.
void addFiles(const std::string& value, const std::string& flag, const int* frames, std::vector<FileArgument>& files) {
  const FramePattern pattern = frames ? FramePattern(value, flag) : FramePattern();
  if (!frames || !pattern.numbered()) return files.push_back({value, flag, value, identityOf(value)});
  const fs::path first(pattern.path(0));
  const bool sameDirectory = first.parent_path() == fs::path(pattern.path(1000000000)).parent_path();
  const fs::path directory = sameDirectory ? identityOf(first.parent_path().empty() ? "." : first.parent_path()) : "";
  for (int frame = 0; frame < *frames; ++frame) {
    const std::string path = pattern.path(frame);
    files.push_back({path, flag, value, sameDirectory ? directory / fs::path(path).filename() : identityOf(path)});
  }
}

// "'a/%04d.png' (--output)" or "'a.png' (--output)".
std::string described(const FileArgument& file) {
  return "'" + file.typed + "' (" + file.flag + ")";
}

}  // namespace

CLI::Option* outputFiles(CLI::Option* option, const int* frames) {
  marked().push_back({option, Role::Output, frames});
  return option;
}

CLI::Option* inputFiles(CLI::Option* option, const int* frames) {
  marked().push_back({option, Role::Input, frames});
  return option;
}

void checkFileArguments(const CLI::App& subcommand) {
  std::vector<FileArgument> outputs, inputs;
  for (const CLI::Option* option : subcommand.get_options())
    for (const Marked& m : marked()) {
      if (m.option != option) continue;
      for (const std::string& value : option->results())
        if (!value.empty()) addFiles(value, flagName(*option), m.frames, m.role == Role::Output ? outputs : inputs);
    }
  // By identity first (every frame of every pattern), then by the file system for the few plain
  // files that exist (a hard link, a second spelling weakly_canonical cannot see through).
  std::unordered_map<std::string, const FileArgument*> written;
  const auto sameFile = [](const FileArgument& a, const FileArgument& b) {
    std::error_code ec;
    if (a.identity == b.identity) return true;
    if (a.typed != a.path || b.typed != b.path) return false;  // frame files: identity only
    return fs::exists(a.path, ec) && fs::exists(b.path, ec) && fs::equivalent(a.path, b.path, ec);
  };
  std::vector<const FileArgument*> plainOutputs;
  for (const FileArgument& output : outputs) {
    const FileArgument* other = nullptr;
    if (auto [at, fresh] = written.emplace(output.identity.string(), &output); !fresh) other = at->second;
    for (const FileArgument* plain : plainOutputs)
      if (!other && output.typed == output.path && sameFile(output, *plain)) other = plain;
    if (other && output.typed == output.path && other->typed == other->path)
      throw ParameterError(output.flag, "'" + output.path + "' is written twice (also by " + other->flag +
                                            "); give each output its own file");
    if (other)
      throw ParameterError(output.flag, described(output) + " and " + described(*other) + " both write '" +
                                            output.path + "'; give each output its own file");
    if (output.typed == output.path) plainOutputs.push_back(&output);
  }
  for (const FileArgument& input : inputs) {
    const auto at = written.find(input.identity.string());
    const FileArgument* output = at == written.end() ? nullptr : at->second;
    for (const FileArgument* plain : plainOutputs)
      if (!output && sameFile(*plain, input)) output = plain;
    if (output)
      throw ParameterError(output->flag, "'" + output->path + "' is also an input (" + input.flag +
                                             (input.typed == input.path ? "" : " '" + input.typed + "'") +
                                             "); refusing to overwrite it, give another output name");
  }
  for (const FileArgument* output : plainOutputs) checkWritableDestination(output->path);
}

}  // namespace texsynth::cli
