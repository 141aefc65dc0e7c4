#pragma once
// Where each library parameter of a subcommand came from on the command line. The library names
// its own option fields (patchSize, shortestCells ...); users typed flags and file names. Each
// subcommand declares one table, and runCommand applies it wherever a ParameterError escapes, so
// no internal name reaches the user and checks on file data become errors about that file.
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace texsynth::cli {

// A flag the user typed ("--grid"), or an input file whose data the library rejected (an exemplar
// too small, a mesh with zero extent): then the error is an InputError naming the file, exit 1.
struct ParameterSource {
  std::string flag;
  std::function<std::string()> file;  // the file's name, known only after parsing
};

// Internal parameter name -> its source.
using ParameterSources = std::map<std::string, ParameterSource, std::less<>>;

inline ParameterSource fromFlag(std::string flag) {
  return {std::move(flag), {}};
}
// `path` is read when the error happens: it must outlive the command (it lives in its args).
ParameterSource fromFile(const std::string& path);
// Several input files of one kind (three exemplars, three masks): all of them are named.
ParameterSource fromFiles(const std::vector<std::string>& paths);

}  // namespace texsynth::cli
