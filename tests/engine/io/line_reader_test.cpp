// The line-numbered cursor under the ascii readers: number parsing, token
// and line positions, byte blocks, and the one-line messages it builds.

#include "engine/io/line_reader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/input_error.h"
#include "tests/engine/io/io_test_util.h"

namespace mtcut::engine {
namespace {

TEST(MeshFileLineReader, ParsesWholeTokensOnly) {
  std::int64_t i = 0;
  EXPECT_TRUE(parse_int("42", i));
  EXPECT_EQ(i, 42);
  EXPECT_TRUE(parse_int("+7", i));
  EXPECT_EQ(i, 7);
  EXPECT_TRUE(parse_int("-9223372036854775808", i));
  for (const char* bad : {"", "+", "4.0", "1e3", "12a", "0x10", "--1", "+-1", "99999999999999999999"})
    EXPECT_FALSE(parse_int(bad, i)) << bad;

  double d = 0;
  EXPECT_TRUE(parse_real("-1.5e-3", d));
  EXPECT_EQ(d, -1.5e-3);
  EXPECT_TRUE(parse_real("+2", d));
  EXPECT_EQ(d, 2.0);
  EXPECT_TRUE(parse_real("nan", d));
  EXPECT_TRUE(std::isnan(d));
  EXPECT_TRUE(parse_real("-inf", d));
  EXPECT_TRUE(std::isinf(d));
  for (const char* bad : {"", "one", "1.0.0", "1e", "1e999", "1,5", "0x1p3"}) EXPECT_FALSE(parse_real(bad, d)) << bad;
}

TEST(MeshFileLineReader, SplitsAndQuotesTokens) {
  const auto tokens = split_tokens(" a\tbb  c \r");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[1], "bb");
  EXPECT_EQ(quote_token("abc"), "'abc'");
  EXPECT_EQ(quote_token(std::string("a\x01\xff", 3)), "'a\\x01\\xFF'");
  EXPECT_EQ(quote_token(std::string(50, 'x')), "'" + std::string(40, 'x') + "...'");
}

TEST(MeshFileLineReader, CountsLinesOfLinesAndTokens) {
  const std::string text = "first line\r\n\n  third 3\nfourth";
  LineReader reader("t.txt", text);
  std::string_view line;
  ASSERT_TRUE(reader.next_line(line));
  EXPECT_EQ(line, "first line");
  EXPECT_EQ(reader.line(), 1u);
  std::string_view token;
  ASSERT_TRUE(reader.peek_token(token));
  EXPECT_EQ(token, "third");
  EXPECT_EQ(reader.line(), 1u);  // peeking does not move
  ASSERT_TRUE(reader.next_token(token));
  EXPECT_EQ(token, "third");
  EXPECT_EQ(reader.line(), 3u);
  EXPECT_EQ(reader.expect_int("a count"), 3);
  EXPECT_EQ(reader.expect_token("a word"), "fourth");
  EXPECT_EQ(reader.line(), 4u);
  EXPECT_TRUE(reader.at_end());
  test::expect_input_error([&] { reader.expect_token("more"); }, {"t.txt: line 4: unexpected end of the file (expected more)"});
}

TEST(MeshFileLineReader, FaultsNameTheLineAndTheToken) {
  const std::string text = "1 2\nx nan -5 1e999\n";
  LineReader reader("f.dat", text);
  reader.expect_int("a");
  reader.expect_int("b");
  test::expect_input_error([&] { reader.expect_int("the count"); }, {"f.dat: line 2: the count 'x' is not an integer"});
  test::expect_input_error([&] { reader.expect_real("x"); }, {"line 2: x 'nan' is not finite"});
  test::expect_input_error([&] { reader.to_count("-5", "n", 10); }, {"n '-5' is negative"});
  test::expect_input_error([&] { reader.to_count("11", "n", 10); }, {"more than the file can hold"});
  EXPECT_EQ(reader.to_count("10", "n", 10), 10u);
  test::expect_input_error([&] { reader.to_real("1e999", "y"); }, {"y '1e999' is not a number"});
  test::expect_input_error([&] { reader.fail_file("whole"); }, {"f.dat: whole"});
}

TEST(MeshFileLineReader, TakesByteBlocksAfterAKeywordLine) {
  const std::string text = std::string("DATA 3\n") + std::string("\x01\n\x02", 3) + "\nEND";
  LineReader reader("b.bin", text);
  EXPECT_EQ(reader.expect_token("key"), "DATA");
  reader.expect_int("n");
  reader.skip_rest_of_line();
  EXPECT_EQ(reader.offset(), 7u);
  EXPECT_EQ(reader.take_bytes(3, "the block"), std::string("\x01\n\x02", 3));
  EXPECT_EQ(reader.expect_token("end"), "END");
  EXPECT_EQ(reader.remaining(), 0u);
  test::expect_input_error([&] { reader.take_bytes(1, "more data"); },
                           {"b.bin", "truncated: more data needs 1 bytes, only 0 are left"});
}

TEST(MeshFileLineReader, ReadsWholeFilesAndRejectsMissingOnes) {
  test::TempDir dir;
  EXPECT_EQ(read_file_bytes(dir.write("a.txt", std::string("x\0y", 3))), std::string("x\0y", 3));
  test::expect_input_error([&] { read_file_bytes(dir.file("none.txt")); }, {"none.txt: no such file"});
  test::expect_input_error([&] { read_file_bytes(dir.write("empty.txt", "")); }, {"empty.txt: the file is empty"});
}

}  // namespace
}  // namespace mtcut::engine
