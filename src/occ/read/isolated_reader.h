// read_shape_isolated: the CAD readers run in a child process, so that a damaged file
// cannot take the caller down.
//
// OpenCASCADE's readers are not hardened against damaged input: random one-byte edits
// of shipped examples made them crash (SIGSEGV inside the STEP transfer, a trimmed
// curve with no basis in a BREP), abort, or loop for ever (a huge curve count),
// taking the process along, which inside FreeCAD is the user's session. Here the
// file is read by a forked child under a memory limit and a deadline, which dies
// with the thread that forked it (PR_SET_PDEATHSIG: a caller killed, by any signal,
// leaves no reader running); it sends the
// shape back as binary BREP (OpenCASCADE's own writer, read back in the parent) or
// its InputError message, with the faces the geometry checker finds invalid. A crash, an abort, a memory overrun or the deadline becomes
// an InputError naming the file; nothing else of the child survives.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace tquad {

// The range a caller may give ReadLimits::seconds (the CLI's --read-timeout, Python's
// read_timeout).
inline constexpr double kMinReadSeconds = 0.001;
inline constexpr double kMaxReadSeconds = 1e6;

// The reader's default deadline grows with the input: kReadSecondsBase plus
// kReadSecondsPerMegabyte per megabyte (10^6 bytes). Reading takes about a second
// per megabyte of STEP here, so a sound file has some thirty times the time it needs,
// and a damaged small file that sends the reader into a loop is refused within
// about half a minute, not five.
inline constexpr double kReadSecondsBase = 30;
inline constexpr double kReadSecondsPerMegabyte = 30;
// The default deadline for an input of `bytes` bytes.
inline double default_read_seconds(unsigned long long bytes) {
  return kReadSecondsBase + kReadSecondsPerMegabyte * static_cast<double>(bytes) / 1e6;
}

struct ReadLimits {
  // Wall time for reading; 0: default_read_seconds of the input's size.
  double seconds = 0;
  unsigned long long memory_bytes = 16ULL << 30;  // address space of the reader
  unsigned long long file_bytes = 4ULL << 30;     // larger input files are refused
};

// The reason given for a face in ReadShape::invalid_faces.
inline constexpr const char* kInvalidFaceReason =
    "OpenCASCADE's checker finds its geometry invalid (a damaged file?)";

struct ReadShape {
  TopoDS_Shape shape;
  // Faces (numbered as ShapeIndex numbers them) whose geometry OpenCASCADE's checker
  // (BRepCheck_Analyzer, run in the child too) finds invalid: a missing wire or
  // pcurve, a wire that does not close, an edge off its surface.
  std::vector<int> invalid_faces;
  // What the reader read past without losing any of the shape (exchange_reader.h),
  // for the front end to show: one line each, naming the file and the entity.
  std::vector<std::string> warnings;
};

// As read_shape (shape_reader.h), in a child process. Also refuses what is not a
// regular file (a directory, /dev/zero) and files over limits.file_bytes.
ReadShape read_shape_isolated(const std::string& path, const ReadLimits& limits = {});

// As read_brep_text, in a child process.
ReadShape read_brep_text_isolated(const std::string& brep, const ReadLimits& limits = {});

// The two halves of the above, for a caller that has the reading done by another process
// than the one meshing: the fuzz targets fork their readers from a small server process
// (fuzz/reader_server.h), since forking the large fuzzing process, and the reader's exit
// from its copy, took much of each run. The reply is the reader process's bytes when it
// read a shape (anything else throws as read_shape_isolated does); decode_shape_reply
// turns them into the shape (std::logic_error for bytes that are no such reply).
std::string read_shape_reply(const std::string& path, const ReadLimits& limits);
std::string read_brep_text_reply(const std::string& brep, const ReadLimits& limits);
ReadShape decode_shape_reply(const std::string& reply);

}  // namespace tquad
