#pragma once
// Numbers of the config file's sections ([server], [web]): the whole value must be the
// number, so that "1.5" workers or "20ms" is refused with the key and the value rather
// than cut or half read.
#include <cstddef>
#include <string>

namespace fleetmap {

// A finite number >= 0 (> 0 unless zero_ok). `section` is as written in the file,
// e.g. "[server]"; the message is "<section> <key>: expected a positive number, got 'v'".
double config_number(const std::string& section, const std::string& key, const std::string& v, bool zero_ok);

// A whole number in [least, most]; the message names the range when it is not the
// default one (1 up to 1e15: "a positive whole number").
size_t config_whole(const std::string& section, const std::string& key, const std::string& v, double least = 1,
                    double most = 1e15);

}  // namespace fleetmap
