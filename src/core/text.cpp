#include "core/text.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace pond {
namespace {

void append_hex(std::string& out, const char* prefix, unsigned value, int digits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%s%0*x", prefix, digits, value);
  out += buf;
}

// The length of the well-formed UTF-8 sequence at text[i] (2..4) and its code point, or 0.
std::size_t utf8_sequence(std::string_view text, std::size_t i, std::uint32_t& code) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  std::size_t n = 0;
  if (b0 >= 0xc2 && b0 <= 0xdf) n = 2, code = b0 & 0x1fu;
  else if (b0 >= 0xe0 && b0 <= 0xef) n = 3, code = b0 & 0x0fu;
  else if (b0 >= 0xf0 && b0 <= 0xf4) n = 4, code = b0 & 0x07u;
  else return 0;
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0u) != 0x80u) return 0;
    code = (code << 6) | (byte(i + k) & 0x3fu);
  }
  // Overlong forms, UTF-16 surrogates and code points past U+10FFFF are not UTF-8.
  if ((n == 3 && code < 0x800) || (n == 4 && (code < 0x10000 || code > 0x10ffff)) ||
      (code >= 0xd800 && code <= 0xdfff))
    return 0;
  return n;
}

bool separator_or_c1(std::uint32_t code) { return (code >= 0x80 && code <= 0x9f) || code == 0x2028 || code == 0x2029; }

// Escapes the non-printable bytes of `text` into `out`; `all` also writes \\ and \' (escaped, quoted)
// and the C-style short forms.
std::string escape(std::string_view text, bool all, bool quote) {
  std::string out;
  out.reserve(text.size() + 2);
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      std::uint32_t code = 0;
      if (const std::size_t n = utf8_sequence(text, i, code)) {
        if (separator_or_c1(code)) append_hex(out, "\\u", code, 4);
        else out.append(text.substr(i, n));
        i += n;
      } else {
        append_hex(out, "\\x", c, 2);
        ++i;
      }
      continue;
    }
    ++i;
    if (c >= 0x20 && c != 0x7f) {
      if (all && (c == '\\' || (quote && c == '\''))) out += '\\';
      out += static_cast<char>(c);
    } else if (all && c == '\n') {
      out += "\\n";
    } else if (all && c == '\r') {
      out += "\\r";
    } else if (all && c == '\t') {
      out += "\\t";
    } else if (all && c == '\0') {
      out += "\\0";
    } else {
      append_hex(out, "\\x", c, 2);
    }
  }
  return out;
}

}  // namespace

std::string escaped(std::string_view text) { return escape(text, true, false); }

std::string quote(std::string_view text) { return "'" + escape(text, true, true) + "'"; }

std::string printable_line(std::string_view message) { return escape(message, false, false); }

std::string number_text(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

std::string number_outside(double value, double lo, double hi) {
  char buf[40];
  for (int digits = 4; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    const double shown = std::strtod(buf, nullptr);
    if (!(shown >= lo && shown <= hi)) break;
  }
  return buf;
}

}  // namespace pond
