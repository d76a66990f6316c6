// User text and numbers in messages (core/text.h): one printable line whatever the user gave.
#include <gtest/gtest.h>

#include <string>

#include "core/text.h"

namespace pond {
namespace {

using namespace std::string_literals;

TEST(Text, ControlBytesAreWrittenOut) {
  EXPECT_EQ(escaped("a\nb"), "a\\nb");
  EXPECT_EQ(escaped("\x1b[31mred"), "\\x1b[31mred");
  EXPECT_EQ(escaped("nul\0here"s), "nul\\0here");
  EXPECT_EQ(escaped("tab\there\r"), "tab\\there\\r");
  EXPECT_EQ(escaped("del\x7f"), "del\\x7f");
  EXPECT_EQ(escaped("back\\slash"), "back\\\\slash");  // so "\n" typed and a newline differ
}

TEST(Text, PrintableUtf8StaysAndBrokenUtf8IsWrittenOut) {
  EXPECT_EQ(escaped("étang/池.json"), "étang/池.json");
  EXPECT_EQ(escaped("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(escaped("\xc3"), "\\xc3");               // cut short
  EXPECT_EQ(escaped("\xc0\xaf"), "\\xc0\\xaf");      // overlong '/'
  EXPECT_EQ(escaped("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(escaped("\xc2\x9b" "2J"), "\\u009b2J");  // C1 CSI: a control sequence on some terminals
  EXPECT_EQ(escaped("line\xe2\x80\xa8sep"), "line\\u2028sep");
}

TEST(Text, QuotedEscapesItsQuote) {
  EXPECT_EQ(quote("it's"), "'it\\'s'");
  EXPECT_EQ(quote("a\nb"), "'a\\nb'");
}

TEST(Text, PrintableLineKeepsWhatIsAlreadyEscaped) {
  const std::string once = "pond: " + quote("a\\b\n\x1b");
  EXPECT_EQ(printable_line(once), once);
  EXPECT_EQ(printable_line("two\nlines\x1b"), "two\\x0alines\\x1b");
  EXPECT_EQ(printable_line("\xc2\x85"), "\\u0085");
}

TEST(Text, NumbersOutsideARangeShowWhy) {
  EXPECT_EQ(number_outside(100.00001, 0.01, 100), "100.00001");
  EXPECT_EQ(number_outside(150, 0.01, 100), "150");
  EXPECT_EQ(number_outside(1e39, 0, 1e6), "1e+39");
  EXPECT_EQ(number_outside(0.0099999999, 0.01, 100), "0.0099999999");
  EXPECT_EQ(number_text(100.00001), "100");
  EXPECT_EQ(number_text(1e-300), "1e-300");
}

}  // namespace
}  // namespace pond
