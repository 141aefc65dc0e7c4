// zlib streams for NRRD's gzip encoding: bounded inflate for reading, streaming deflate
// (gzip wrapper) for writing, so neither side holds two copies of a large volume.
#include <zlib.h>

#include <algorithm>
#include <climits>

#include "texsynth/core/error.h"
#include "volume_codecs.h"

namespace texsynth::volume_codec {

std::string inflateExactly(const std::string& path, std::string_view compressed, std::uint64_t expectedBytes) {
  z_stream stream{};
  if (inflateInit2(&stream, 15 + 32) != Z_OK) throw InternalError("zlib inflateInit2 failed");  // +32: gzip or zlib
  auto fail = [&](const std::string& problem) {
    inflateEnd(&stream);
    throw InputError(path, problem);
  };
  std::string out(expectedBytes, '\0');
  std::size_t consumed = 0, produced = 0;
  char extra = 0;  // once all samples are out, the stream's end (and CRC check) must follow
  for (;;) {
    bool full = produced == expectedBytes;
    // zlib counts in 32-bit units: feed and drain at most 1 GiB per call.
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + consumed));
    stream.avail_in = uInt(std::min<std::size_t>(compressed.size() - consumed, std::size_t(1) << 30));
    stream.next_out = reinterpret_cast<Bytef*>(full ? &extra : out.data() + produced);
    stream.avail_out = full ? 1 : uInt(std::min<std::uint64_t>(expectedBytes - produced, std::uint64_t(1) << 30));
    uInt inBefore = stream.avail_in, outBefore = stream.avail_out;
    int result = inflate(&stream, Z_NO_FLUSH);
    consumed += inBefore - stream.avail_in;
    if (!full) produced += outBefore - stream.avail_out;
    if (result == Z_STREAM_END) {
      if (consumed < compressed.size())
        fail(std::to_string(compressed.size() - consumed) + " bytes follow the end of the gzip data");
      break;
    }
    if (full && stream.avail_out == 0) fail("gzip data holds more samples than the header says");
    if (result == Z_BUF_ERROR && consumed == compressed.size()) {  // input exhausted
      if (!full) break;                                            // reported below with the byte counts
      fail("truncated: gzip data ends before its end marker and checksum");
    }
    if (result != Z_OK)
      fail("corrupt gzip data: " + std::string(stream.msg ? stream.msg : "zlib error " + std::to_string(result)));
  }
  inflateEnd(&stream);
  if (produced < expectedBytes)
    throw InputError(path, "truncated: gzip data holds only " + std::to_string(produced) + " of the " +
                               std::to_string(expectedBytes) + " bytes of samples the header says");
  return out;
}

struct GzipWriter::State {
  z_stream stream{};
  std::string buffer = std::string(std::size_t(1) << 20, '\0');
};

GzipWriter::GzipWriter(std::function<void(const char*, std::size_t)> sink, int level)
    : state_(std::make_unique<State>()), sink_(std::move(sink)) {
  // windowBits 15+16: a gzip wrapper, which is what NRRD readers (teem, ITK, Slicer) expect.
  if (deflateInit2(&state_->stream, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw InternalError("zlib deflateInit2 failed");
}

GzipWriter::~GzipWriter() {
  deflateEnd(&state_->stream);
}

void GzipWriter::pump(int flush) {
  z_stream& s = state_->stream;
  int result = Z_OK;
  do {
    s.next_out = reinterpret_cast<Bytef*>(state_->buffer.data());
    s.avail_out = uInt(state_->buffer.size());
    result = deflate(&s, flush);
    if (result == Z_STREAM_ERROR) throw InternalError("zlib deflate failed");
    std::size_t produced = state_->buffer.size() - s.avail_out;
    if (produced) sink_(state_->buffer.data(), produced);
  } while (s.avail_out == 0 || (flush == Z_FINISH && result != Z_STREAM_END));
}

void GzipWriter::write(const char* data, std::size_t size) {
  z_stream& s = state_->stream;
  while (size > 0) {
    uInt chunk = uInt(std::min<std::size_t>(size, std::size_t(1) << 30));
    s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
    s.avail_in = chunk;
    pump(Z_NO_FLUSH);
    data += chunk;
    size -= chunk;
  }
}

void GzipWriter::finish() {
  state_->stream.next_in = nullptr;
  state_->stream.avail_in = 0;
  pump(Z_FINISH);
}

}  // namespace texsynth::volume_codec
