// Reading a user's input file (scenario, vehicle, track, contact cases,
// contact-geometry table, profile, measured irregularity) with bounded cost:
// the path must name a regular file (not a folder, a device such as
// /dev/zero, or a pipe) no larger than kMaxInputFileBytes, checked before a
// byte is read. Messages that echo input quote at most one line of it,
// shortened to kMaxQuotedChars (quote_input).
//
// Failures throw railsim::InputError naming the file.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace railsim {

// Largest input file accepted [bytes] (64 MiB; the largest shipped input, the
// RSGEO contact-geometry table, is 0.5 MB).
inline constexpr std::uintmax_t kMaxInputFileBytes = 64ull << 20;
// Longest piece of input text quoted in a message [characters].
inline constexpr std::size_t kMaxQuotedChars = 80;

// Throws InputError unless `path` is a readable regular file of at most
// `max_bytes`; `what` names the kind of file in the message ("scenario",
// "contact-geometry table", ...).
void check_input_file(const std::string& path, std::string_view what,
                      std::uintmax_t max_bytes = kMaxInputFileBytes);

// check_input_file, then the whole content.
std::string read_input_file(const std::string& path, std::string_view what,
                            std::uintmax_t max_bytes = kMaxInputFileBytes);

// `text` for a message: its first line, at most kMaxQuotedChars characters,
// with "..." when something was left off; control bytes (below 0x20, 0x7f:
// a terminal escape sequence, a NUL) written as \xNN.
std::string quote_input(std::string_view text);

}  // namespace railsim
