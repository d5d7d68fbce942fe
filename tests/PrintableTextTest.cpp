// printableText: what a file someone sent holds is shown, never obeyed. Every byte a terminal acts
// on (C0 controls, DEL, C1 controls in UTF-8 and the raw bytes 0x80..0x9f that some terminals
// take as C1) and every byte that is not part of valid UTF-8 becomes an escape; text people write,
// in any script, passes unchanged.
#include <ptview/io/PrintableText.h>

#include <gtest/gtest.h>

#include <string>

namespace ptview {
namespace {

TEST(PrintableText, TerminalControlsBecomeEscapes) {
    EXPECT_EQ(printableText("\x1b]0;owned\x07"), "\\e]0;owned\\x07"); // sets the window title
    EXPECT_EQ(printableText("\x1b[31mred"), "\\e[31mred");             // colours
    EXPECT_EQ(printableText("done\rfake line"), "done\\rfake line");    // overwrites the line
    EXPECT_EQ(printableText("one\ntwo"), "one\\ntwo");
    EXPECT_EQ(printableText("a\tb"), "a\\tb");
    EXPECT_EQ(printableText(std::string("nul\0byte", 8)), "nul\\x00byte");
    EXPECT_EQ(printableText("del\x7f"), "del\\x7f");
}

TEST(PrintableText, C1ControlsAreEscapedInUtf8AndAsRawBytes) {
    EXPECT_EQ(printableText("\xc2\x9b" "31m"), "\\xc2\\x9b31m"); // U+009B, CSI, as UTF-8
    EXPECT_EQ(printableText("\xc2\x85"), "\\xc2\\x85");          // U+0085, next line
    EXPECT_EQ(printableText("\x9b" "31m"), "\\x9b31m");          // a raw CSI byte: not UTF-8 at all
    EXPECT_EQ(printableText("\xc2\xa0"), "\xc2\xa0");            // U+00A0, the first character past C1
}

TEST(PrintableText, InvalidAndOverlongUtf8IsEscapedBytewise) {
    EXPECT_EQ(printableText("\xff\xfe"), "\\xff\\xfe");
    EXPECT_EQ(printableText("\xc0\xaf"), "\\xc0\\xaf");                 // overlong '/'
    EXPECT_EQ(printableText("\xe0\x80\x9b"), "\\xe0\\x80\\x9b");       // overlong CSI
    EXPECT_EQ(printableText("\xc3"), "\\xc3");                         // cut short at the end
    EXPECT_EQ(printableText("\xc3" "A"), "\\xc3" "A");                 // cut short by ASCII
    EXPECT_EQ(printableText("\xed\xa0\x80"), "\\xed\\xa0\\x80");       // a surrogate
    EXPECT_EQ(printableText("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80"); // past U+10FFFF
}

TEST(PrintableText, PrintableTextPassesUnchanged) {
    std::string ascii;
    for (char c = 0x20; c < 0x7F; ++c) ascii += c;
    EXPECT_EQ(printableText(ascii), ascii);                         // backslashes included
    EXPECT_EQ(printableText("caf\xc3\xa9"), "caf\xc3\xa9");         // é
    EXPECT_EQ(printableText("\xe6\x97\xa5\xe6\x9c\xac"), "\xe6\x97\xa5\xe6\x9c\xac"); // 日本
    EXPECT_EQ(printableText("\xf0\x9f\x94\xa5"), "\xf0\x9f\x94\xa5"); // an emoji, four bytes
    EXPECT_EQ(printableText(""), "");
}

TEST(PrintableText, EveryByteValueComesOutInert) {
    for (int byte = 0; byte < 256; ++byte) {
        const std::string text = "<" + std::string(1, static_cast<char>(byte)) + ">";
        const std::string shown = printableText(text);
        for (char c : shown) {
            const unsigned char out = static_cast<unsigned char>(c);
            EXPECT_TRUE(out >= 0x20 && out < 0x7F) << "byte " << byte << " came out as " << shown;
        }
    }
}

// A note of several lines (a load and its warnings, a line each) keeps its lines in a panel;
// everything else is escaped as printableText escapes it.
TEST(PrintableText, LinesKeepTheirBreaksAndNothingElse) {
    EXPECT_EQ(printableLines("opened a.json\nwarning: b\x1b]0;t\x07\r"), "opened a.json\nwarning: b\\e]0;t\\x07\\r");
    EXPECT_EQ(printableText("a\nb"), "a\\nb");
}

} // namespace
} // namespace ptview
