// The vocabulary file (format in vocabulary.h): Save, Load, the body and its FNV-1a identity.

#include <cstring>
#include <stdexcept>

#include "dslam/core/binary_io.h"
#include "dslam/place_recognition/vocabulary.h"
#include "vocabulary_tree.h"

namespace dslam {
namespace {

constexpr char kMagic[8] = {'D', 'S', 'L', 'A', 'M', 'V', 'O', 'C'};
constexpr size_t kHeaderBytes = 20;  // magic, version, identity
constexpr size_t kParamBytes = 20;   // k, L, descriptor bytes, nodes, words
constexpr size_t kNodeBytes = 4 + 8 + Vocabulary::kDescriptorBytes;

[[noreturn]] void Fail(const std::string& path, const std::string& reason) {
  throw std::runtime_error("Vocabulary::Load: " + path + ": " + reason);
}

// The nodes of `bytes` (from offset 40) into `tree`; the parameters are read already.
void ParseNodes(const std::string& bytes, size_t num_nodes, VocabularyTree* tree) {
  for (size_t i = 0; i < num_nodes; ++i) {
    const size_t at = kHeaderBytes + kParamBytes + i * kNodeBytes;
    Descriptor d;
    std::memcpy(d.data(), bytes.data() + at + 12, d.size());
    const std::uint32_t node =
        tree->AddNode(static_cast<std::uint32_t>(GetLittleEndian(bytes, at, 4)), d);
    tree->weight[node] = GetF64(bytes, at + 4);
  }
}

}  // namespace

std::string SerialiseBody(const VocabularyTree& tree) {
  std::string out;
  out.reserve(kParamBytes + tree.parent.size() * kNodeBytes);
  PutU32(static_cast<std::uint32_t>(tree.branching), &out);
  PutU32(static_cast<std::uint32_t>(tree.levels), &out);
  PutU32(Vocabulary::kDescriptorBytes, &out);
  PutU32(static_cast<std::uint32_t>(tree.parent.size()), &out);
  PutU32(static_cast<std::uint32_t>(tree.node_of_word.size()), &out);
  for (size_t i = 0; i < tree.parent.size(); ++i) {
    PutU32(tree.parent[i], &out);
    PutF64(tree.weight[i], &out);
    out.append(reinterpret_cast<const char*>(tree.descriptor[i].data()), tree.descriptor[i].size());
  }
  return out;
}

void Vocabulary::Save(const std::string& path) const {
  if (empty()) throw std::logic_error("Vocabulary::Save: empty vocabulary");
  std::string bytes(kMagic, sizeof(kMagic));
  PutU32(kFormatVersion, &bytes);
  PutU64(tree_->identity, &bytes);
  bytes += SerialiseBody(*tree_);
  WriteFileAtomically(path, bytes, "Vocabulary::Save");
}

Vocabulary Vocabulary::Load(const std::string& path) {
  const std::string bytes = ReadWholeFile(path, "Vocabulary::Load");
  if (bytes.size() < sizeof(kMagic)) Fail(path, "truncated: shorter than the magic string");
  if (std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) {
    Fail(path, "wrong magic: not a dslam vocabulary file");
  }
  if (bytes.size() < kHeaderBytes + kParamBytes) Fail(path, "truncated header");
  const std::uint64_t version = GetLittleEndian(bytes, 8, 4);
  if (version != kFormatVersion) {
    Fail(path, "unsupported format version " + std::to_string(version) + " (this build reads " +
                   std::to_string(kFormatVersion) + ")");
  }
  auto tree = std::make_shared<VocabularyTree>();
  tree->branching = static_cast<int>(GetLittleEndian(bytes, 20, 4));
  tree->levels = static_cast<int>(GetLittleEndian(bytes, 24, 4));
  const std::uint64_t descriptor_bytes = GetLittleEndian(bytes, 28, 4);
  const std::uint64_t num_nodes = GetLittleEndian(bytes, 32, 4);
  const std::uint64_t num_words = GetLittleEndian(bytes, 36, 4);
  const std::uint64_t expected = kHeaderBytes + kParamBytes + num_nodes * kNodeBytes;
  if (bytes.size() < expected) {
    Fail(path, "truncated: " + std::to_string(bytes.size()) + " bytes, the header promises " +
                   std::to_string(expected));
  }
  if (bytes.size() > expected) Fail(path, "corrupt: bytes after the last node");
  const std::uint64_t identity = GetLittleEndian(bytes, 12, 8);
  if (Fnv1a64(bytes.data() + kHeaderBytes, bytes.size() - kHeaderBytes) != identity) {
    Fail(path, "corrupt: the contents do not match the identity (FNV-1a hash) in the header");
  }
  if (descriptor_bytes != kDescriptorBytes || tree->branching < 2 || tree->levels < 1) {
    Fail(path, "corrupt: descriptor size, branching or levels out of range");
  }
  ParseNodes(bytes, num_nodes, tree.get());
  const std::string problem = tree->Index();
  if (!problem.empty()) Fail(path, "corrupt: " + problem);
  if (tree->node_of_word.size() != num_words) Fail(path, "corrupt: the word count differs");
  tree->identity = identity;
  return Vocabulary(std::move(tree));
}

}  // namespace dslam
