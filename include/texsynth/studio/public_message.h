#pragma once
// The studio's error messages are read by whoever sent the request: they name the request and the
// user's uploads, not the private files behind them. The server writes scratch files (an export
// read back, an upload being checked) whose paths a library error may quote; these go.
#include <string>

namespace texsynth::studio {

// `message` with every scratch or temporary path replaced by the name it stands for:
// ".../texsynth-scratch-XXXXXX/volume.vdb" -> "volume.vdb",
// ".../.model.texsynth-tmp-HOST-PID-N.glb" -> "model.glb", a scratch folder -> "a temporary folder".
std::string withoutTemporaryPaths(const std::string& message);

}  // namespace texsynth::studio
