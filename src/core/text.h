#pragma once
// User text and numbers as messages show them. Whatever the user gave (a path, a JSON key, a word
// of a script, a flag's value) goes through escaped() or quote() before it is echoed, so a message
// stays one line and nothing in it reaches the terminal as a control sequence.
#include <string>
#include <string_view>

namespace pond {

// `text` with every byte a terminal could act on written out: \n \r \t \0 and \\ as in C, other
// control bytes and DEL as \xNN, bytes that are not UTF-8 as \xNN, the C1 controls and the line
// and paragraph separators (U+0080..U+009F, U+2028, U+2029) as \uNNNN. Printable UTF-8 stays.
std::string escaped(std::string_view text);
// escaped(text) between single quotes, a quote inside written \'.
std::string quote(std::string_view text);
// A whole message made one printable line: the bytes escaped() writes out as \xNN or \uNNNN are,
// backslashes and quotes are not (so text already escaped is unchanged). main's last guard.
std::string printable_line(std::string_view message);

// A number for a message: %.6g ("100", "1e+300", "0.25").
std::string number_text(double value);
// `value`, which lies outside [lo, hi], with the fewest digits (at least 4) that still read as a
// number outside it: 100.00001 against [0.01, 100] is "100.00001", not "100".
std::string number_outside(double value, double lo, double hi);

}  // namespace pond
