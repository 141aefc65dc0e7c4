// JPEG encoder through libjpeg-turbo (SIMD DCT and Huffman coding; several times faster than
// stb's). Quality means what it meant with stb, the IJG scale 1..100, and like stb we keep
// full-resolution chroma above quality 90 and subsample it 2x2 at 90 and below.
// jpeglib.h uses FILE and size_t without including their headers.
// clang-format off
#include <cstdio>
#include <jpeglib.h>
// clang-format on

#include <csetjmp>
#include <cstdlib>
#include <memory>
#include <vector>

#include "image_codecs.h"
#include "texsynth/core/error.h"

namespace texsynth::image_codec {
namespace {

// libjpeg reports errors through a callback that must not return; it jumps back to the
// setjmp in compressRgb (exceptions must not unwind through the C library's frames).
struct ErrorManager {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void onError(j_common_ptr info) {
  auto* errors = reinterpret_cast<ErrorManager*>(info->err);
  errors->base.format_message(info, errors->message);
  std::longjmp(errors->jump, 1);
}

struct FreeBuffer {
  void operator()(unsigned char* p) const { std::free(p); }
};

// Compresses 8-bit RGB rows into a malloc'd buffer; false (with errors.message) on failure.
// Only trivially destructible locals live here, so longjmp skips no destructor.
bool compressRgb(const std::uint8_t* rgb, int width, int height, int quality, ErrorManager& errors,
                 unsigned char*& buffer, unsigned long& size) {
  jpeg_compress_struct info;
  info.err = jpeg_std_error(&errors.base);
  errors.base.error_exit = onError;
  if (setjmp(errors.jump)) {
    jpeg_destroy_compress(&info);
    return false;
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = JDIMENSION(width);
  info.image_height = JDIMENSION(height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  int chroma = quality > 90 ? 1 : 2;
  info.comp_info[0].h_samp_factor = info.comp_info[0].v_samp_factor = chroma;
  info.comp_info[1].h_samp_factor = info.comp_info[1].v_samp_factor = 1;
  info.comp_info[2].h_samp_factor = info.comp_info[2].v_samp_factor = 1;
  jpeg_start_compress(&info, TRUE);
  std::size_t rowBytes = std::size_t(width) * 3;
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(rgb + info.next_scanline * rowBytes);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  return true;
}

}  // namespace

std::string encodeJpeg(const std::string& path, const Image& image, int quality) {
  std::vector<std::uint8_t> rgb = quantizedBytes(image, 3);  // JPEG has no alpha
  ErrorManager errors{};
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  bool ok = compressRgb(rgb.data(), image.width, image.height, quality, errors, buffer, size);
  std::unique_ptr<unsigned char, FreeBuffer> owned(buffer);
  if (!ok) throw OutputError(path, std::string("the JPEG encoder failed: ") + errors.message);
  return std::string(reinterpret_cast<const char*>(buffer), size);
}

}  // namespace texsynth::image_codec
