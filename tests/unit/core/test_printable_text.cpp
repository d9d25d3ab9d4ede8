// SPDX-License-Identifier: MIT
// UTF-8 decoding and the escaping/truncation of user text echoed in messages.
#include "formflow/core/printable_text.hpp"

#include <gtest/gtest.h>

namespace formflow {
namespace {

TEST(Utf8, SequenceLengthsOfValidCharacters) {
  EXPECT_EQ(utf8_sequence_length("a"), 1u);
  EXPECT_EQ(utf8_sequence_length("é"), 2u); // U+00E9
  EXPECT_EQ(utf8_sequence_length("ε̄"), 2u); // U+03B5, then a combining mark
  EXPECT_EQ(utf8_sequence_length("≤"), 3u); // U+2264
  EXPECT_EQ(utf8_sequence_length("😀"), 4u); // U+1F600
}

TEST(Utf8, InvalidSequencesHaveLengthZero) {
  EXPECT_EQ(utf8_sequence_length("\xff"), 0u);             // never a lead byte
  EXPECT_EQ(utf8_sequence_length("\x80"), 0u);             // a lone continuation byte
  EXPECT_EQ(utf8_sequence_length("\xc3"), 0u);             // truncated
  EXPECT_EQ(utf8_sequence_length("\xc0\xaf"), 0u);         // overlong '/'
  EXPECT_EQ(utf8_sequence_length("\xed\xa0\x80"), 0u);     // a UTF-16 surrogate
  EXPECT_EQ(utf8_sequence_length("\xf4\x90\x80\x80"), 0u); // above U+10FFFF
}

TEST(PrintableText, ValidTextPassesUnchanged) {
  EXPECT_EQ(printable_text("friction.mu = 0.1 ≤ 1\t(tab kept)"),
            "friction.mu = 0.1 ≤ 1\t(tab kept)");
}

TEST(PrintableText, ControlBytesAndInvalidUtf8AreEscaped) {
  EXPECT_EQ(printable_text(std::string("a\x01z\n", 4)), "a\\x01z\\x0A");
  EXPECT_EQ(printable_text("bad \xff byte"), "bad \\xFF byte");
  EXPECT_EQ(printable_text(std::string("nul\0!", 5)), "nul\\x00!");
}

TEST(PrintableText, LongTextIsCutAtACharacterBoundary) {
  const std::string key(100000, 'k');
  const std::string shown = printable_text(key, 50);
  EXPECT_EQ(shown, std::string(50, 'k') + "…");
  // A multi-byte character is never split: 20 × "≤" (3 bytes) cut at 10 bytes keeps 3 of them.
  std::string relations;
  for (int k = 0; k < 20; ++k) relations += "≤";
  EXPECT_EQ(printable_text(relations, 10), "≤≤≤…");
}

} // namespace
} // namespace formflow
