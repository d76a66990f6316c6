#pragma once
// Replayed input for tests and recordings (`pond demo --script FILE`). A text file, one event a
// line; blank lines are ignored, and a word starting with # begins a comment to the end of the
// line; words are separated by spaces:
//
//   frame N key NAME [shift] [ctrl] [alt]     press and release a key before frame N is drawn
//   frame N click X Y [shift] [ctrl] [alt]    left click at pixel (X, Y) (top-left origin):
//                                             a splash; shift = position, ctrl = explosion
//   frame N drag left|middle|right X0 Y0 X1 Y1  press at (X0, Y0), move to (X1, Y1), release
//                                             (left = orbit, middle = pan, right = tree wind)
//   frame N press left|middle|right X Y [mods]  press a button at (X, Y) and keep it down
//   frame N move X Y                          move the cursor (a drag over several frames)
//   frame N release left|middle|right X Y     release the button there; a left press on a body
//                                             grabs it, the moves drag it, the release lets it go
//   frame N drop X Y                          the cursor to (X, Y), then key O: drop a ball there
//   frame N remove-body I                     the panel's "remove" of body I
//   frame N add-ball                          the panel's "add ball"
//   frame N scroll DY                         mouse wheel (DY > 0 zooms in)
//   frame N resize W H                        resize the window to W x H
//   frame N screenshot FILE                   save frame N as a PNG (written atomically)
//   frame N save FILE / frame N load FILE     save the pond to a checkpoint / load one (F5 / F9
//                                             with FILE; docs/checkpoints.md)
//   frame N minimize / frame N restore        iconify / restore the window (needs a window
//                                             manager; frames while minimized draw nothing)
//
// Frames count from 0; events of one frame run in file order, after the window's own events.
// NAME is a letter, a digit, F1..F12, or one of SPACE ESCAPE ENTER TAB HOME LEFT RIGHT UP DOWN
// [ ] - = . , (also as LEFT_BRACKET RIGHT_BRACKET MINUS EQUAL PERIOD COMMA).
// X and Y are finite pixels within +-65536, DY within +-100 wheel steps, N within [0, 2^62).
// Anything else (a control byte in a line too) is an InputError naming the file, the line and the
// word (pond exits 2).
#include <cstdint>
#include <string>
#include <vector>

#include "app/demo/input_event.h"

namespace pond::app::demo {

struct ScriptEvent {
  std::int64_t frame = 0;
  InputEvent event;  // scripted = true; resize: x, y = the new window size
};

struct Script {
  std::vector<ScriptEvent> events;        // sorted by frame, file order within a frame
  std::vector<std::string> screenshots;  // InputEvent::screenshot indexes these (screenshot events)
  std::vector<int> screenshot_lines;     // the line of each
  std::vector<std::string> checkpoints;  // and these (save and load events)
};

Script parse_script(const std::string& text, const std::string& source);
Script load_script(const std::string& path);  // "" = an empty script

// GLFW_KEY_* for a script key name, or -1.
int key_from_name(const std::string& name);

}  // namespace pond::app::demo
