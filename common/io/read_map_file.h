#pragma once
// A map file read in the format its name announces: the AMRL vector maps
// (../shared/maps/*.vectormap.txt, common/io/amrl_import.h) end in ".vectormap.txt";
// every other name is read as the seed format (seed 000 appendix A, SPEC 3). The one
// place that knows the naming rule, for every program that takes a map file.
#include <string>
#include <string_view>

#include "common/io/amrl_import.h"
#include "common/map/map.h"

namespace fleetmap {

enum class MapFileFormat { Seed, Amrl };

inline constexpr std::string_view kAmrlSuffix = ".vectormap.txt";

// By the name alone (case-sensitive, as the AMRL repository names its files).
MapFileFormat map_file_format(std::string_view path);

// Reads and validates the file; throws MapFormatError ("file:line: expected ...").
// amrl and report apply to an AMRL file only: the seed format carries its own heights.
Map read_map_file(const std::string& path, const AmrlOptions& amrl = {}, AmrlReport* report = nullptr);

}  // namespace fleetmap
