#include "test_support.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "texsynth/core/error.h"
#include "texsynth/core/random.h"

namespace texsynth::test {
namespace fs = std::filesystem;

TempDir::TempDir() {
  std::string pattern = (fs::temp_directory_path() / "texsynth-test-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

void expectInputError(const std::function<void()>& read, const std::string& path, const std::string& problem) {
  try {
    read();
    ADD_FAILURE() << "no error reading " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << "message: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type for " << path << ": " << e.what();
  }
}

void expectParameterError(const std::function<void()>& run, const std::string& parameter) {
  try {
    run();
    ADD_FAILURE() << "accepted bad " << parameter;
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), parameter);
  }
}

Image makeTestPattern(int width, int height, unsigned seed) {
  Image image(width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float noise = uniform01(hashKey(seed, latticeId(x / 3, y / 3)));
      float waves = 0.5f + 0.25f * std::sin(0.35f * x + 0.8f * std::sin(0.21f * y));
      image.at(x, y, 0) = 0.6f * waves + 0.4f * noise;
      image.at(x, y, 1) = 0.5f + 0.5f * std::sin(0.17f * (x + 2 * y));
      image.at(x, y, 2) = noise;
    }
  return image;
}

std::string loopbackExchange(int port, const std::string& request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(std::uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::string answer;
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      ::send(fd, request.data(), request.size(), 0) == ssize_t(request.size())) {
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) answer.append(buffer, std::size_t(n));
  }
  ::close(fd);
  return answer;
}

}  // namespace texsynth::test
