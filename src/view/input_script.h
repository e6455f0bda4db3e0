#pragma once
// A replay of viewer input, one event per line, for tests and reproducible demos:
//   FRAME key w|a|s|d|q|e|shift down|up    a key pressed or released before frame FRAME is drawn
//   FRAME look DX DY                        mouse movement (pixels) with the right button held
//   FRAME wheel STEPS                       scroll
//   FRAME mode fly|orbit                    camera mode
//   FRAME resize WIDTH HEIGHT               asks the window system for a new window size
//   FRAME drop PATH                         a file dropped on the window
//   FRAME set OPTION VALUE                  as the controls: technique, debug-view, exposure, lights, tile
//   FRAME preset-save PATH                  the particle preset editor's Save
//   FRAME print-camera                      prints the camera as a --camera value on stdout
// Blank lines and lines starting with # are skipped. Frames count from 0.
#include <cstdint>
#include <string>
#include <vector>

namespace lll::view {

struct ScriptEvent {
  uint32_t frame = 0;
  std::string verb;
  std::vector<std::string> args;
  std::string where;  // "FILE:LINE", for messages
};

// Throws InputError naming the file and line for an unknown verb, a wrong argument count or a bad number.
std::vector<ScriptEvent> loadInputScript(const std::string& path);
std::vector<ScriptEvent> parseInputScript(const std::string& text, const std::string& source);

// A script argument as a finite number; throws InputError naming the event.
float scriptNumber(const ScriptEvent& event, size_t arg);

}  // namespace lll::view
