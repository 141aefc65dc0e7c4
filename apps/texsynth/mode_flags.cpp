#include "mode_flags.h"

#include <algorithm>

#include "texsynth/core/error.h"

namespace texsynth::cli {

void rejectFlagsOutsideMode(const CLI::App& sub, const std::vector<ModeFlag>& table, const std::string& mode,
                            const std::string& modePhrase) {
  for (const ModeFlag& entry : table) {
    const CLI::Option* option = sub.get_option_no_throw(entry.flag);
    if (!option || option->count() == 0) continue;
    if (std::find(entry.modes.begin(), entry.modes.end(), mode) != entry.modes.end()) continue;
    std::string users;
    for (const std::string& m : entry.modes) users += (users.empty() ? "" : ", ") + m;
    throw ParameterError(entry.flag, "does nothing " + modePhrase + " (it applies to " + users + ")");
  }
}

}  // namespace texsynth::cli
