//! @file Checkpoint container: exact round trip; truncation, corruption and mismatch detected.
#include <fstream>
#include <numeric>
#include <sstream>

#include <gtest/gtest.h>

#include "hvi/common/binary.hpp"
#include "hvi/common/error.hpp"
#include "hvi/io/checkpoint.hpp"
#include "test_support.hpp"

namespace hvi::io::test {
namespace {
namespace fs = std::filesystem;

const std::string header = "solver = \"sph\"\n" + sampleScene();

std::vector<double> bodyData(std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = std::sin(static_cast<double>(i)) * 1e3;
  v[0] = -0.0;
  return v;
}

void writeSample(const fs::path& file, std::size_t n = 100000) {
  writeCheckpointFile(file, header, [&](std::ostream& out) {
    BinaryWriter w(out, "test body");
    w.value<long>(1234);
    w.array(bodyData(n));
    w.string("tail");
  });
}

void readSample(std::istream& in, std::size_t n = 100000) {
  BinaryReader r(in, "test body");
  EXPECT_EQ(r.value<long>(), 1234);
  const auto v = r.array<double>();
  ASSERT_EQ(v.size(), n);
  const auto expected = bodyData(n);
  for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(sameBits(v[i], expected[i])) << i;
  EXPECT_EQ(r.string(), "tail");
}

std::string inputErrorOf(const fs::path& file, const std::function<void(std::istream&)>& body) {
  try {
    readCheckpointFile(file, body);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    return msg;
  }
  ADD_FAILURE() << "no InputError for " << file;
  return {};
}

TEST(Checkpoint, Fnv1a64MatchesPublishedVectors) {
  // Reference values from the FNV authors' test suite (isthe.com/chongo/tech/comp/fnv).
  EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar", 6), 0x85944171f73967e8ULL);
  // Incremental hashing equals one-shot hashing (the writer hashes in blocks).
  EXPECT_EQ(fnv1a64("bar", 3, fnv1a64("foo", 3)), fnv1a64("foobar", 6));
}

TEST(Checkpoint, RoundTripsHeaderAndBodyExactly) {
  ScratchDir dir;
  writeSample(dir / "c.ckpt");
  EXPECT_EQ(readCheckpointFile(dir / "c.ckpt", [](std::istream& in) { readSample(in); }), header);
  EXPECT_EQ(readCheckpointFile(dir / "c.ckpt", nullptr), header);  // header only
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"c.ckpt"});
  // 20-byte prefix + header + 8 + 8 + body(800000 + 8) + 8 + 8 + 4 + 8 trailer.
  EXPECT_EQ(fs::file_size(dir / "c.ckpt"), 20 + header.size() + 8 + 8 + 800000 + 8 + 4 + 16);
}

TEST(Checkpoint, EmptyBodyAndEmptyHeader) {
  ScratchDir dir;
  writeCheckpointFile(dir / "e.ckpt", "", [](std::ostream&) {});
  EXPECT_EQ(readCheckpointFile(dir / "e.ckpt", [](std::istream& in) { EXPECT_EQ(in.peek(), EOF); }), "");
}

TEST(Checkpoint, EveryTruncationIsRejected) {
  ScratchDir dir;
  writeSample(dir / "full.ckpt", 10);
  const auto size = fs::file_size(dir / "full.ckpt");
  // Every possible length short of complete, including lengths that cut the header.
  for (std::uintmax_t len = 0; len < size; ++len) {
    fs::copy_file(dir / "full.ckpt", dir / "cut.ckpt", fs::copy_options::overwrite_existing);
    fs::resize_file(dir / "cut.ckpt", len);
    bool called = false;
    inputErrorOf(dir / "cut.ckpt", [&](std::istream&) { called = true; });
    EXPECT_FALSE(called) << "body handed to the solver from a " << len << "-byte file";
  }
  // A large file cut in the middle of the body.
  writeSample(dir / "big.ckpt");
  fs::resize_file(dir / "big.ckpt", fs::file_size(dir / "big.ckpt") / 2);
  EXPECT_NE(inputErrorOf(dir / "big.ckpt", nullptr).find("truncated"), std::string::npos);
}

void flipBit(const fs::path& file, std::streamoff at) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(at);
  char c = 0;
  f.get(c);
  f.seekp(at);
  f.put(static_cast<char>(c ^ 0x10));
}

TEST(Checkpoint, CorruptedBytesAreRejected) {
  ScratchDir dir;
  writeSample(dir / "c.ckpt");
  const auto size = static_cast<std::streamoff>(fs::file_size(dir / "c.ckpt"));
  for (std::streamoff at : {std::streamoff(25), size / 2, size - 20, size - 12, size - 1}) {
    // header, body, body length, checksum
    fs::copy_file(dir / "c.ckpt", dir / "x.ckpt", fs::copy_options::overwrite_existing);
    flipBit(dir / "x.ckpt", at);
    const std::string msg = inputErrorOf(dir / "x.ckpt", nullptr);
    EXPECT_TRUE(msg.find("checksum") != std::string::npos || msg.find("truncated") != std::string::npos)
        << "byte " << at << ": " << msg;
  }
}

TEST(Checkpoint, ForeignFilesAndOtherVersionsAreRejected) {
  ScratchDir dir;
  EXPECT_NE(inputErrorOf(dir / "missing.ckpt", nullptr).find("cannot read"), std::string::npos);
  std::ofstream(dir / "text.ckpt") << "[scene]\nthis is a TOML file, long enough to have a header\n";
  EXPECT_NE(inputErrorOf(dir / "text.ckpt", nullptr).find("not an hvi checkpoint"), std::string::npos);
  writeSample(dir / "v.ckpt", 3);
  flipBit(dir / "v.ckpt", 9);  // version 1 -> 0x1001
  EXPECT_NE(inputErrorOf(dir / "v.ckpt", nullptr).find("format version 4097"), std::string::npos);
}

TEST(Checkpoint, ReaderThatDoesNotMatchTheWriterIsRejected) {
  ScratchDir dir;
  writeSample(dir / "c.ckpt", 10);
  // Reads less than was written: a solver whose state layout changed.
  const auto readOne = [](std::istream& in) { BinaryReader(in, "test body").value<long>(); };
  EXPECT_NE(inputErrorOf(dir / "c.ckpt", readOne).find("left unread"), std::string::npos);
  // Reads more: stops at the body's end, never in the trailer.
  const std::string msg = inputErrorOf(dir / "c.ckpt", [](std::istream& in) {
    readSample(in, 10);
    BinaryReader(in, "test body").value<double>();
  });
  EXPECT_NE(msg.find("ends inside a value"), std::string::npos) << msg;
}

// The one binary reader and writer of all checkpoint bodies (hvi/common/binary.hpp).
TEST(BinaryIo, RoundTripIsExactAndLayoutIsCountThenElements) {
  std::stringstream buf;
  BinaryWriter w(buf, "test body");
  w.value<std::int32_t>(-7);
  w.array(std::vector<double>{-0.0, 1.5});
  const std::vector<int> raw{1, 2, 3};
  w.elements(raw.data(), raw.size());
  w.string("abc");
  EXPECT_EQ(buf.str().size(), 4u + 8 + 16 + 12 + 8 + 3);
  BinaryReader r(buf, "test body");
  EXPECT_EQ(r.value<std::int32_t>(), -7);
  const auto v = r.array<double>();
  ASSERT_EQ(v.size(), 2u);
  EXPECT_TRUE(sameBits(v[0], -0.0));
  std::vector<int> back;
  r.elements(back, 3);
  EXPECT_EQ(back, raw);
  EXPECT_EQ(r.string(), "abc");
}

TEST(BinaryIo, ShortStreamsWrongCountsAndFailedWritesAreErrors) {
  const auto messageOf = [](const std::string& bytes, auto read) {
    std::stringstream in(bytes);
    BinaryReader r(in, "test body");
    try {
      read(r);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(messageOf("abc", [](BinaryReader& r) { r.value<double>(); }),
            "test body: the stream ends inside a value");
  std::stringstream two;
  BinaryWriter(two, "test body").array(std::vector<double>{1.0, 2.0});
  EXPECT_NE(messageOf(two.str(),
                      [](BinaryReader& r) {
                        std::vector<double> v;
                        r.array(v, 3, "density");
                      })
                .find("array 'density' has 2 values, this run has 3"),
            std::string::npos);
  const std::uint64_t huge = std::uint64_t(1) << 62;
  const std::string hugeCount(reinterpret_cast<const char*>(&huge), sizeof huge);
  EXPECT_NE(messageOf(hugeCount, [](BinaryReader& r) { r.array<double>(); }).find("implausible"),
            std::string::npos);
  EXPECT_NE(messageOf(hugeCount, [](BinaryReader& r) { r.string(); }).find("implausible"),
            std::string::npos);
  std::ostringstream failed;
  failed.setstate(std::ios::badbit);
  EXPECT_THROW(BinaryWriter(failed, "test body").value(1.0), OutputError);
}

}  // namespace
}  // namespace hvi::io::test
