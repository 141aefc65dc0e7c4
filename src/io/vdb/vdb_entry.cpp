// The module's entry point (vdb_module.h).
#include "vdb_module.h"

extern "C" const texsynth::vdb_module::Codec* texsynthVdbCodec() {
  static const texsynth::vdb_module::Codec codec{&texsynth::vdb_module::encode, &texsynth::vdb_module::decode};
  return &codec;
}
