// OpenEXR reader through the Imf C++ API, reading from memory so that a short file is an
// ordinary exception rather than a read past the end. Channels Y, YA, RGB or RGBA; any sample
// type (half, float, uint) is converted to float by the library. The writer is
// image_exr_write.cpp.
#include <OpenEXR/Iex.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>

#include <cstring>
#include <mutex>
#include <vector>

#include "image_codecs.h"
#include "image_exr_support.h"
#include "texsynth/core/error.h"

namespace texsynth::image_codec {
namespace {

class MemoryInput : public Imf::IStream {
 public:
  MemoryInput(const std::string& name, std::string_view bytes) : Imf::IStream(name.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    // Written so that no sum can wrap: a header may seek to any 64-bit offset.
    if (n < 0 || position_ > bytes_.size() || std::uint64_t(n) > bytes_.size() - position_)
      throw Iex::InputExc("the file is truncated (it ends at byte " + std::to_string(bytes_.size()) + ")");
    std::memcpy(c, bytes_.data() + position_, std::size_t(n));
    position_ += std::uint64_t(n);
    return position_ < bytes_.size();
  }
  std::uint64_t tellg() override { return position_; }
  void seekg(std::uint64_t position) override { position_ = position; }

 private:
  std::string_view bytes_;
  std::uint64_t position_ = 0;
};

// Bounds OpenEXR's own allocations for absurd headers (it checks these while reading one).
void limitHeaderSizes() {
  static std::once_flag once;
  std::call_once(once, [] {
    Imf::Header::setMaxImageSize(65536, 65536);
    Imf::Header::setMaxTileSize(65536, 65536);
  });
}

// The file's channel names mapped to the Image's channels, in order.
std::vector<std::string> chooseChannels(const std::string& path, const Imf::ChannelList& list) {
  auto has = [&](const char* name) { return list.findChannel(name) != nullptr; };
  std::vector<std::string> names;
  if (has("R") && has("G") && has("B"))
    names = {"R", "G", "B"};
  else if (has("Y"))
    names = {"Y"};
  else {
    std::string all;
    int count = 0;
    for (auto it = list.begin(); it != list.end(); ++it, ++count)
      all += (all.empty() ? "" : ", ") + std::string(it.name());
    if (count != 1)
      throw InputError(
          path, "OpenEXR file has no R,G,B or Y channels (it has: " + (all.empty() ? std::string("none") : all) + ")");
    names = {all};  // a lone channel of any name is read as gray
  }
  if (has("A") && (names.size() == 3 || names[0] == "Y")) names.push_back("A");
  for (const std::string& name : names) {
    const Imf::Channel* channel = list.findChannel(name.c_str());
    if (channel->xSampling != 1 || channel->ySampling != 1)
      throw InputError(path, "OpenEXR channel '" + name + "' is subsampled, which is not supported");
  }
  return names;
}

struct ExrLayout {
  Imath::Box2i window;
  int width = 0, height = 0;
  std::vector<std::string> channels;
  int bits = 32;
  bool eightBitLevels = false;  // half floats standing for k/255 (kExrLevelsAttribute)
};

ExrLayout layoutOf(const std::string& path, const Imf::Header& header, std::uint64_t fileBytes) {
  ExrLayout layout;
  layout.window = header.dataWindow();
  std::int64_t width = std::int64_t(layout.window.max.x) - layout.window.min.x + 1;
  std::int64_t height = std::int64_t(layout.window.max.y) - layout.window.min.y + 1;
  layout.channels = chooseChannels(path, header.channels());
  checkImageSize(path, width, height, std::int64_t(layout.channels.size()));
  layout.width = int(width);
  layout.height = int(height);
  bool allHalf = true;
  for (const std::string& name : layout.channels)
    allHalf &= header.channels().findChannel(name.c_str())->type == Imf::HALF;
  layout.bits = allHalf ? 16 : 32;
  auto* levels = header.findTypedAttribute<Imf::IntAttribute>(kExrLevelsAttribute);
  layout.eightBitLevels = allHalf && levels && levels->value() == kEightBitLevels;
  // Generous for every OpenEXR compression (deflate-based ones stay near 1032:1, PIZ and B44
  // far below); only a file that lies about its size gets near it.
  checkPlausibleSize(path, fileBytes, layout.width, layout.height, int(layout.channels.size()), layout.bits / 8, 4096,
                     Format::Exr);
  return layout;
}

// Our writer's half floats back to the exact 8-bit levels they stand for.
void snapToEightBitLevels(Image& image) {
  std::size_t rowValues = std::size_t(image.width) * std::size_t(image.channels);
  parallelFor(0, image.height, [&](std::int64_t y) {
    for (std::size_t i = std::size_t(y) * rowValues, end = i + rowValues; i < end; ++i)
      image.pixels[i] = fromByte(toByte(image.pixels[i]));
  });
}

// Runs `body`, turning OpenEXR's exceptions into one InputError naming the file.
template <typename Body>
auto guarded(const std::string& path, Body&& body) {
  limitHeaderSizes();
  try {
    return body();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, std::string("cannot decode OpenEXR: ") + e.what());
  }
}

}  // namespace

ImageFileInfo infoExr(const std::string& path, std::string_view bytes) {
  return guarded(path, [&] {
    MemoryInput stream(path, bytes);
    Imf::InputFile file(stream);
    ExrLayout layout = layoutOf(path, file.header(), bytes.size());
    return ImageFileInfo{layout.width, layout.height, int(layout.channels.size()), layout.bits, "exr"};
  });
}

Image decodeExr(const std::string& path, std::string_view bytes) {
  return guarded(path, [&] {
    MemoryInput stream(path, bytes);
    Imf::InputFile file(stream);
    ExrLayout layout = layoutOf(path, file.header(), bytes.size());
    int channels = int(layout.channels.size());
    Image image(layout.width, layout.height, channels);
    // OpenEXR addresses pixels by absolute (data-window) coordinates; Slice::Make shifts the
    // base so that the window's corner lands on pixels[0].
    std::size_t xStride = sizeof(float) * channels, yStride = xStride * layout.width;
    char* origin = reinterpret_cast<char*>(image.pixels.data());
    Imf::FrameBuffer frame;
    for (int c = 0; c < channels; ++c)
      frame.insert(layout.channels[c].c_str(),
                   Imf::Slice::Make(Imf::FLOAT, origin + c * sizeof(float), layout.window, xStride, yStride));
    file.setFrameBuffer(frame);
    if (!file.isComplete()) throw InputError(path, "truncated: the OpenEXR file is missing pixel data");
    matchExrThreadsToLimit();
    file.readPixels(layout.window.min.y, layout.window.max.y);
    if (layout.eightBitLevels) snapToEightBitLevels(image);
    return image;
  });
}

}  // namespace texsynth::image_codec
