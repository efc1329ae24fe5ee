#include "io/text_output.h"

#include <charconv>

namespace tquad {

void append_double(std::string& text, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text.append(buffer, result.ptr);
}

void append_integer(std::string& text, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text.append(buffer, result.ptr);
}

void append_double_within(std::string& text, double value, int width) {
  char buffer[40];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  for (int digits = 17; result.ptr - buffer > width && digits > 1; --digits) {
    result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  }
  text.append(buffer, result.ptr);
}

void flush_if_large(std::ostream& out, std::string& text) {
  if (text.size() > (1u << 20)) flush_text(out, text);
}

void flush_text(std::ostream& out, std::string& text) {
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  text.clear();
}

}  // namespace tquad
