#include "parse_errors.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace texsynth::cli {
namespace {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::vector<std::string> subcommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

// Every long and short flag of `app` (and the global ones of its parent), as typed.
std::vector<std::string> flagNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* scope = &app; scope; scope = scope->get_parent())
    for (const CLI::Option* option : scope->get_options()) {
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
      for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
  return names;
}

// The first argument that is not a flag or a global flag's value: what the user meant as a command.
std::string typedCommand(const std::vector<std::string>& arguments) {
  static const std::vector<std::string> takesValue = {"--seed", "--threads"};
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& a = arguments[i];
    if (a.rfind("-", 0) != 0) return a;
    if (std::find(takesValue.begin(), takesValue.end(), a) != takesValue.end()) ++i;
  }
  return "";
}

std::string unknownCommand(const CLI::App& app, const std::string& typed) {
  const std::vector<std::string> commands = subcommandNames(app);
  if (typed.empty()) return "give a command (" + joined(commands) + "); 'texsynth --help' explains each";
  const std::string nearest = nearestName(typed, commands);
  return "unknown command '" + typed + "'" + (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") +
         " (commands: " + joined(commands) + ")";
}

// The subcommand the user named, or nullptr.
const CLI::App* namedSubcommand(const CLI::App& app, const std::vector<std::string>& arguments) {
  const std::string typed = typedCommand(arguments);
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == typed) return sub;
  return nullptr;
}

// The first argument that looks like a flag `sub` does not have ("--sze"), or "". Reported
// before anything else CLI11 complains of, since it is usually why a value is missing.
std::string unknownFlag(const CLI::App& sub, const std::vector<std::string>& arguments) {
  static const std::regex negativeNumber("-[0-9.].*");
  const std::vector<std::string> known = flagNames(sub);
  for (const std::string& argument : arguments) {
    if (argument.size() < 2 || argument[0] != '-' || argument == "--" || std::regex_match(argument, negativeNumber))
      continue;
    const std::string flag = argument.substr(0, argument.find('='));
    if (std::find(known.begin(), known.end(), flag) == known.end()) return flag;
  }
  return "";
}

std::string unknownFlagMessage(const CLI::App& sub, const std::string& flag) {
  const std::string nearest = nearestName(flag, flagNames(sub));
  return sub.get_name() + ": unknown flag '" + flag + "'" +
         (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") + " ('texsynth " + sub.get_name() +
         " --help' lists them)";
}

// "The following argument(s) were not expected: a b" without an unknown flag among them.
std::string unexpectedArguments(const CLI::App& app, const std::string& list,
                                const std::vector<std::string>& arguments) {
  const CLI::App* sub = namedSubcommand(app, arguments);
  if (!sub) return unknownCommand(app, typedCommand(arguments));
  std::vector<std::string> words;
  std::istringstream split(list);
  for (std::string word; split >> word;) words.push_back(word);
  std::reverse(words.begin(), words.end());  // CLI11 lists them last first
  return sub->get_name() + ": unexpected argument" + (words.size() > 1 ? "s" : "") + " '" + joined(words) +
         "' ('texsynth " + sub->get_name() + " --help' shows what it takes)";
}

}  // namespace

std::string nearestName(const std::string& typed, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(2, typed.size() / 3) + 1;
  for (const std::string& candidate : candidates)
    if (const std::size_t d = editDistance(typed, candidate); d < bestDistance) best = candidate, bestDistance = d;
  return best;
}

std::string describeParseError(const CLI::ParseError& error, const CLI::App& app,
                               const std::vector<std::string>& arguments) {
  const std::string what = error.what();
  if (const CLI::App* sub = namedSubcommand(app, arguments))
    if (const std::string flag = unknownFlag(*sub, arguments); !flag.empty()) return unknownFlagMessage(*sub, flag);
  std::smatch m;
  if (what == "A subcommand is required") return unknownCommand(app, typedCommand(arguments));
  if (std::regex_match(what, m, std::regex("The following arguments? (?:was|were) not expected: (.*)")))
    return unexpectedArguments(app, m[1], arguments);
  if (std::regex_match(what, m, std::regex("(\\S+): At Most 1 required but received (\\d+)")))
    return std::string(m[1]) + " takes one value, got " + std::string(m[2]) + "; give it once";
  if (std::regex_match(what, m, std::regex("(\\S+): At Most (\\d+) required but received (\\d+)")))
    return std::string(m[1]) + " takes at most " + std::string(m[2]) + " values, got " + std::string(m[3]);
  if (std::regex_match(what, m, std::regex("(\\S+): At least (\\d+) required but received (\\d+)")))
    return std::string(m[1]) + " needs at least " + std::string(m[2]) + " values, got " + std::string(m[3]);
  if (std::regex_match(what, m, std::regex("Expected exactly (\\d+) arguments to (\\S+), got (\\d+)")))
    return std::string(m[2]) + " takes " + std::string(m[1]) + " values, got " + std::string(m[3]);
  if (std::regex_match(what, m, std::regex("Could not convert: (\\S+) = (.*)")))
    return std::string(m[1]) + ": '" + std::string(m[2]) + "' is not a value it takes (see --help)";
  if (std::regex_match(what, m, std::regex("(\\S+) excludes (\\S+)")))
    return std::string(m[1]) + " and " + std::string(m[2]) + " cannot be given together: drop one";
  if (std::regex_match(what, m, std::regex("(\\S+) requires (\\S+)")))
    return std::string(m[1]) + " needs " + std::string(m[2]) + " too";
  if (std::regex_match(what, m, std::regex("(\\S+): \\d+ required (.*) missing")))
    return std::string(m[1]) + " needs a value (" + std::string(m[2]) + ")";
  if (std::regex_match(what, m, std::regex("(\\S+): (.*) not in \\{(.*)\\}"))) {
    std::vector<std::string> choices;
    std::istringstream split(m[3].str());
    for (std::string choice; std::getline(split, choice, ',');) choices.push_back(choice);
    const std::string nearest = nearestName(m[2], choices);
    return std::string(m[1]) + ": '" + std::string(m[2]) + "' is not one of " + joined(choices) +
           (nearest.empty() ? "" : "; did you mean '" + nearest + "'?");
  }
  return what;  // ours (validators name the flag), or already plain ("--mesh is required")
}

}  // namespace texsynth::cli
