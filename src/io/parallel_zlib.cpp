#include "parallel_zlib.h"

#include <zlib.h>

#include <algorithm>
#include <vector>

#include "image_codecs.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth::image_codec {
namespace {

constexpr std::size_t kWindowBytes = 32768;  // deflate's largest match distance

// Raw deflate of data[begin..end), primed with the window before `begin`; ends with a sync
// flush (byte-aligned, more blocks may follow) or, for the last chunk, the final block.
std::string deflateChunk(const std::uint8_t* data, std::size_t begin, std::size_t end, bool last,
                         const ParallelZlibSettings& settings) {
  z_stream stream{};
  if (deflateInit2(&stream, settings.level, Z_DEFLATED, -15, 8, settings.strategy) != Z_OK)
    throw InternalError("zlib deflateInit2 failed");
  struct End {
    z_stream* s;
    ~End() { deflateEnd(s); }
  } ender{&stream};
  std::size_t primed = std::min(begin, kWindowBytes);
  if (primed > 0 && deflateSetDictionary(&stream, data + begin - primed, uInt(primed)) != Z_OK)
    throw InternalError("zlib deflateSetDictionary failed");
  // deflateBound covers the data; a sync flush adds at most an empty stored block (5 bytes).
  std::string out(deflateBound(&stream, uLong(end - begin)) + 16, '\0');
  stream.next_in = const_cast<Bytef*>(data + begin);
  stream.avail_in = uInt(end - begin);
  int flush = last ? Z_FINISH : Z_SYNC_FLUSH;
  for (;;) {
    std::size_t produced = std::size_t(stream.total_out);
    stream.next_out = reinterpret_cast<Bytef*>(out.data() + produced);
    stream.avail_out = uInt(out.size() - produced);
    int result = deflate(&stream, flush);
    if (result == Z_STREAM_ERROR) throw InternalError("zlib deflate failed");
    bool done = last ? result == Z_STREAM_END : stream.avail_in == 0 && stream.avail_out > 0;
    if (done) break;
    out.resize(out.size() * 2);
  }
  out.resize(std::size_t(stream.total_out));
  return out;
}

// The two-byte zlib header: deflate with a 32 KiB window, the level hint zlib itself writes.
std::string zlibHeader(int level) {
  int hint = level < 2 ? 0 : level < 6 ? 1 : level == 6 ? 2 : 3;
  unsigned header = 0x7800u | unsigned(hint) << 6;
  header += 31 - header % 31;
  return {char(header >> 8), char(header & 0xff)};
}

}  // namespace

std::string compressZlibParallel(const std::uint8_t* data, std::size_t size, const ParallelZlibSettings& settings) {
  std::size_t chunkBytes =
      std::clamp<std::size_t>(settings.chunkBytes, 1, std::size_t(1) << 30);  // zlib counts in uInt
  std::size_t chunks = std::max<std::size_t>((size + chunkBytes - 1) / chunkBytes, 1);
  std::vector<std::string> pieces(chunks);
  std::vector<uLong> checksums(chunks);
  parallelFor(0, std::int64_t(chunks), [&](std::int64_t i) {
    std::size_t begin = std::size_t(i) * chunkBytes, end = std::min(size, begin + chunkBytes);
    pieces[i] = deflateChunk(data, begin, end, std::size_t(i) + 1 == chunks, settings);
    checksums[i] = adler32(adler32(0, nullptr, 0), data + begin, uInt(end - begin));
  });
  std::size_t total = 6;
  for (const std::string& piece : pieces) total += piece.size();
  std::string out = zlibHeader(settings.level);
  out.reserve(total);
  uLong checksum = checksums[0];
  for (std::size_t i = 0; i < chunks; ++i) {
    out += pieces[i];
    if (i > 0) {
      std::size_t length = std::min(size, (i + 1) * chunkBytes) - i * chunkBytes;
      checksum = adler32_combine(checksum, checksums[i], z_off_t(length));
    }
    std::string().swap(pieces[i]);  // free as we go: big images hold two copies otherwise
  }
  appendBigEndian32(out, std::uint32_t(checksum));
  return out;
}

}  // namespace texsynth::image_codec
