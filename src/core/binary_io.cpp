// Little-endian byte helpers, FNV-1a and write-then-rename (dslam/core/binary_io.h).
#include "dslam/core/binary_io.h"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace dslam {

void PutU32(std::uint32_t v, std::string* out) {
  for (int i = 0; i < 4; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

void PutU64(std::uint64_t v, std::string* out) {
  for (int i = 0; i < 8; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

void PutF64(double v, std::string* out) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof(double));
  PutU64(bits, out);
}

std::uint64_t GetLittleEndian(const std::string& bytes, std::size_t offset, int size) {
  std::uint64_t v = 0;
  for (int i = 0; i < size; ++i) {
    v |= static_cast<std::uint64_t>(static_cast<std::uint8_t>(bytes[offset + i])) << (8 * i);
  }
  return v;
}

double GetF64(const std::string& bytes, std::size_t offset) {
  const std::uint64_t bits = GetLittleEndian(bytes, offset, 8);
  double v = 0.0;
  std::memcpy(&v, &bits, sizeof(double));
  return v;
}

std::uint64_t Fnv1a64(const char* data, std::size_t size) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<std::uint8_t>(data[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string FormatIdentity(std::uint64_t identity) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(identity));
  return text;
}

void WriteFileAtomically(const std::string& path, const std::string& bytes,
                         const std::string& who) {
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error(who + ": cannot write " + temporary);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error(who + ": cannot rename " + temporary + " to " + path + ": " +
                             error.message());
  }
}

std::string ReadWholeFile(const std::string& path, const std::string& who) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(who + ": " + path + ": cannot open the file");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(who + ": " + path + ": read error");
  return bytes;
}

}  // namespace dslam
