// runCommand: the one place where a subcommand's errors get the names the user typed.
#include <new>
#include <stdexcept>
#include <string>

#include "cli_common.h"
#include "texsynth/core/error.h"

namespace texsynth::cli {

namespace {

Error outOfMemory(const Command& command) {
  return Error(command.memoryFlags.empty() ? "out of memory" : "out of memory: lower " + command.memoryFlags);
}

}  // namespace

void runCommand(const Command& command) {
  try {
    command.run();
  } catch (const ParameterError& e) {
    auto found = command.sources.find(e.parameter());
    if (found == command.sources.end()) throw;  // already a flag, or a name the CLI gave itself
    const ParameterSource& source = found->second;
    const std::string file = source.file ? source.file() : "";
    if (!file.empty()) throw InputError(file, e.problem());
    if (source.flag.empty()) throw;  // built-in data (no file given): keep the library's words
    throw ParameterError(source.flag, e.problem());
  } catch (const std::bad_alloc&) {
    // Unwinding has freed the command's memory, so this message can be built.
    throw outOfMemory(command);
  } catch (const std::length_error&) {  // a container asked for more than it can ever hold
    throw outOfMemory(command);
  }
}

}  // namespace texsynth::cli
