// The studio's error messages without the private paths behind them.
#include "texsynth/studio/public_message.h"

#include <gtest/gtest.h>

namespace texsynth::studio {
namespace {

TEST(PublicMessage, TemporaryPathsBecomeTheNamesTheyStandFor) {
  EXPECT_EQ(withoutTemporaryPaths("/tmp/texsynth-scratch-Ab12Cd/volume.vdb: file does not exist"),
            "volume.vdb: file does not exist");
  EXPECT_EQ(withoutTemporaryPaths("cannot write '/home/u/out/.model.texsynth-tmp-0a1b2c3d-4242-7.glb': disk full"),
            "cannot write 'model.glb': disk full");
  EXPECT_EQ(withoutTemporaryPaths("cannot create a scratch directory in /tmp/texsynth-scratch-XyZ123, sorry"),
            "cannot create a scratch directory in a temporary folder, sorry");
  EXPECT_EQ(withoutTemporaryPaths("curve: not valid JSON at line 1, column 3"),
            "curve: not valid JSON at line 1, column 3");
}

}  // namespace
}  // namespace texsynth::studio
