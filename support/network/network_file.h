#pragma once
// Lab 06's networks as text, one statement a line, so a visualization can be changed without recompiling:
//
//   # a DVR of the MRI head
//   processor VolumeSource source volume=file volume_file=volumes/anatomical.nii
//   processor RayTraversal raycaster compositing=dvr shading=phong
//   connect source.volume -> raycaster.volume
//
// `processor <Type> <name> [key=value ...]` creates a registered type under an instance name and sets its
// parameters; `connect <processor>.<output> -> <processor>.<input>` wires two declared processors. Words are
// separated by blanks; a value holding blanks is written in double quotes (file="my data/head.nii"), with no
// escapes. '#' at the start of a word begins a comment to the end of the line; blank lines are ignored.
#include "support/network/processor_network.h"
#include "support/network/processor_registry.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace gsv {

// Builds the network the text describes. Throws gsv::Error "<source_name>:<line>: <what>" for an unknown
// keyword, a missing type or name, a word that is not key=value, an unknown type or parameter, a value the
// parameter refuses (Params::set's message), a name used twice, and every mistake connect() refuses; after the last line,
// "<source_name>: raycaster.entry is not connected" for required inputs left open.
Network parse_network(std::string_view text, const std::string& source_name, const ProcessorRegistry& registry);

// parse_network on a file, with its path as the source name; throws gsv::Error when it cannot be read.
Network read_network_file(const std::filesystem::path& path, const ProcessorRegistry& registry);

// The network as parse_network reads it: processors in the order added with the parameters that were set
// (declared order), a blank line, then the connections in the order made. Comments are not kept. Throws
// gsv::Error for a parameter value no network file can hold (a double quote or a line break in it).
std::string network_text(const Network& network);

// Throws gsv::Error naming the file when it cannot be written.
void write_network_file(const std::filesystem::path& path, const Network& network);

}  // namespace gsv
