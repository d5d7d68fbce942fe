#pragma once
// Text from a file, made safe to print on a terminal or show in a panel: metadata, names and
// paths in a file someone sent may hold control sequences (a window title, colours, "\r" that
// overwrites a line), which are shown as escapes instead of being obeyed.

#include <string>
#include <string_view>

namespace ptview {

// `text` with every control character (C0, DEL, and C1 in UTF-8) and every byte that is not part
// of valid UTF-8 written as an escape: "\n", "\r", "\t", "\e" for ESC, "\x9b" otherwise; a
// backslash stays a backslash. Printable UTF-8 passes unchanged.
std::string printableText(std::string_view text);
// The same but for line breaks, which stay: for text of several lines shown as such (a panel's
// note of a load and its warnings, one per line).
std::string printableLines(std::string_view text);

// Prints "ptview: MESSAGE" and a newline on stderr, through printableText: the one way messages
// that quote names, paths and values from files (errors, warnings) reach the terminal.
void printMessage(std::string_view message);

} // namespace ptview
