#include "app/demo/script.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/errors.h"
#include "core/output_file.h"
#include "core/text.h"

namespace pond::app::demo {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Cursor positions within the largest window (--size) and beyond it by as much; wheel steps an
// event, a mouse's wheel giving 1 a notch.
constexpr double kMaxPixel = 65536, kMaxScroll = 100;

class LineParser {
 public:
  LineParser(const std::string& source, int line, std::vector<std::string> words)
      : where_(escaped(source) + " line " + std::to_string(line)), words_(std::move(words)) {}

  [[noreturn]] void fail(const std::string& what) const { throw InputError("--script " + where_ + ": " + what); }

  bool done() const { return next_ >= words_.size(); }
  std::string word(const char* what) {
    if (done()) fail(std::string("missing ") + what);
    return words_[next_++];
  }
  // A finite number within [-limit, limit]: nan, inf and 1e30 never reach the camera or a held body.
  double number(const char* what, double limit) {
    const std::string w = word(what);
    double v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (end != w.data() + w.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
      fail(std::string(what) + " " + quote(w) + " is not a number");
    if (ec != std::errc() || !(std::fabs(v) <= limit))
      fail(std::string(what) + " " + quote(w) + " is outside [-" + number_text(limit) + ", " + number_text(limit) + "]");
    return v;
  }
  double pixel(const char* what) { return number(what, kMaxPixel); }
  std::int64_t integer(const char* what, std::int64_t lo, std::int64_t hi) {
    const std::string w = word(what);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (end != w.data() + w.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
      fail(std::string(what) + " " + quote(w) + " is not an integer");
    if (ec != std::errc() || v < lo || v > hi)
      fail(std::string(what) + " " + quote(w) + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }
  int modifiers() {
    int mods = 0;
    while (!done()) {
      const std::string m = word("modifier");
      if (m == "shift") mods |= GLFW_MOD_SHIFT;
      else if (m == "ctrl") mods |= GLFW_MOD_CONTROL;
      else if (m == "alt") mods |= GLFW_MOD_ALT;
      else fail("unknown modifier " + quote(m) + " (shift, ctrl, alt)");
    }
    return mods;
  }
  void end() const {
    if (!done()) fail("unexpected " + quote(words_[next_]));
  }

 private:
  std::string where_;
  std::vector<std::string> words_;
  std::size_t next_ = 0;
};

using Kind = InputEvent::Kind;

// An output a script line names, checked as every output is (a folder that is not there, a name
// too long), the refusal naming the line.
void checked_output(const LineParser& p, const char* verb, const std::string& file) {
  try {
    check_output_path(file);
  } catch (const InputError& e) {
    p.fail(std::string(verb) + ": " + e.what());
  }
}

// The words of `line`, up to a word starting with # (a comment); InputError for a control byte
// (a NUL, an escape), which no script word holds.
std::vector<std::string> words_of(const std::string& line, const std::string& source, int number) {
  for (std::size_t k = 0; k < line.size(); ++k)
    if (const auto c = static_cast<unsigned char>(line[k]); (c < 0x20 && c != '\t' && c != '\r') || c == 0x7f)
      throw InputError("--script " + escaped(source) + " line " + std::to_string(number) + ": control byte " +
                       escaped(line.substr(k, 1)) + " at column " + std::to_string(k + 1));
  std::istringstream split(line);
  std::vector<std::string> words;
  for (std::string w; split >> w && w[0] != '#';) words.push_back(w);
  return words;
}

constexpr const char* kEvents =
    "key, click, drag, press, move, release, drop, remove-body, add-ball, scroll, resize, screenshot, save, load, "
    "minimize, restore";

}  // namespace

int key_from_name(const std::string& name) {
  const std::string n = upper(name);
  if (n.size() == 1 && n[0] >= 'A' && n[0] <= 'Z') return GLFW_KEY_A + (n[0] - 'A');
  if (n.size() == 1 && n[0] >= '0' && n[0] <= '9') return GLFW_KEY_0 + (n[0] - '0');
  if (n.size() >= 2 && n[0] == 'F' && std::all_of(n.begin() + 1, n.end(), ::isdigit)) {
    const int f = std::stoi(n.substr(1));
    if (f >= 1 && f <= 12) return GLFW_KEY_F1 + (f - 1);
  }
  static const std::pair<const char*, int> kNames[] = {
      {"SPACE", GLFW_KEY_SPACE}, {"ESCAPE", GLFW_KEY_ESCAPE}, {"ENTER", GLFW_KEY_ENTER},
      {"TAB", GLFW_KEY_TAB}, {"HOME", GLFW_KEY_HOME}, {"LEFT", GLFW_KEY_LEFT}, {"RIGHT", GLFW_KEY_RIGHT},
      {"UP", GLFW_KEY_UP}, {"DOWN", GLFW_KEY_DOWN}, {"[", GLFW_KEY_LEFT_BRACKET},
      {"LEFT_BRACKET", GLFW_KEY_LEFT_BRACKET}, {"]", GLFW_KEY_RIGHT_BRACKET},
      {"RIGHT_BRACKET", GLFW_KEY_RIGHT_BRACKET}, {"-", GLFW_KEY_MINUS}, {"MINUS", GLFW_KEY_MINUS},
      {"=", GLFW_KEY_EQUAL}, {"EQUAL", GLFW_KEY_EQUAL}, {".", GLFW_KEY_PERIOD}, {"PERIOD", GLFW_KEY_PERIOD},
      {",", GLFW_KEY_COMMA}, {"COMMA", GLFW_KEY_COMMA}};
  for (const auto& [text, key] : kNames)
    if (n == text) return key;
  return -1;
}

Script parse_script(const std::string& text, const std::string& source) {
  Script script;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::vector<std::string> words = words_of(line, source, number);
    if (words.empty()) continue;
    LineParser p(source, number, std::move(words));
    if (p.word("'frame'") != "frame") p.fail("a line must start with 'frame N'");
    const std::int64_t frame = p.integer("frame number", 0, INT64_MAX / 2);
    auto add = [&](InputEvent e) {
      e.scripted = true;
      script.events.push_back({frame, e});
    };
    const std::string verb = p.word((std::string("event (") + kEvents + ")").c_str());
    if (verb == "key") {
      const std::string name = p.word("key name");
      const int key = key_from_name(name);
      if (key < 0) p.fail("unknown key " + quote(name));
      const int mods = p.modifiers();
      add({.kind = Kind::key, .code = key, .action = GLFW_PRESS, .mods = mods});
      add({.kind = Kind::key, .code = key, .action = GLFW_RELEASE, .mods = mods});
    } else if (verb == "click") {
      const double x = p.pixel("x"), y = p.pixel("y");
      const int mods = p.modifiers();
      add({.kind = Kind::cursor, .x = x, .y = y});
      add({.kind = Kind::button, .code = GLFW_MOUSE_BUTTON_LEFT, .action = GLFW_PRESS, .mods = mods, .x = x, .y = y});
      add({.kind = Kind::button, .code = GLFW_MOUSE_BUTTON_LEFT, .action = GLFW_RELEASE, .mods = mods, .x = x, .y = y});
    } else if (verb == "drag") {
      const std::string b = p.word("button (left, middle, right)");
      const int button = b == "left" ? GLFW_MOUSE_BUTTON_LEFT
                         : b == "middle" ? GLFW_MOUSE_BUTTON_MIDDLE
                         : b == "right" ? GLFW_MOUSE_BUTTON_RIGHT : -1;
      if (button < 0) p.fail("unknown button " + quote(b) + " (left, middle, right)");
      const double x0 = p.pixel("x0"), y0 = p.pixel("y0"), x1 = p.pixel("x1"), y1 = p.pixel("y1");
      const int mods = p.modifiers();
      add({.kind = Kind::cursor, .x = x0, .y = y0});
      add({.kind = Kind::button, .code = button, .action = GLFW_PRESS, .mods = mods, .x = x0, .y = y0});
      add({.kind = Kind::cursor, .x = x1, .y = y1});
      add({.kind = Kind::button, .code = button, .action = GLFW_RELEASE, .mods = mods, .x = x1, .y = y1});
    } else if (verb == "press" || verb == "release") {
      // A drag spread over frames (with `move`): on a body, press grabs it and release lets it go.
      const std::string b = p.word("button (left, middle, right)");
      const int button = b == "left" ? GLFW_MOUSE_BUTTON_LEFT
                         : b == "middle" ? GLFW_MOUSE_BUTTON_MIDDLE
                         : b == "right" ? GLFW_MOUSE_BUTTON_RIGHT : -1;
      if (button < 0) p.fail("unknown button " + quote(b) + " (left, middle, right)");
      const double x = p.pixel("x"), y = p.pixel("y");
      const int mods = p.modifiers();
      add({.kind = Kind::cursor, .x = x, .y = y});
      add({.kind = Kind::button, .code = button, .action = verb == "press" ? GLFW_PRESS : GLFW_RELEASE, .mods = mods,
           .x = x, .y = y});
    } else if (verb == "move") {
      const double x = p.pixel("x"), y = p.pixel("y");
      add({.kind = Kind::cursor, .x = x, .y = y});
    } else if (verb == "drop") {  // the cursor to (x, y), then the drop-a-ball key
      const double x = p.pixel("x"), y = p.pixel("y");
      add({.kind = Kind::cursor, .x = x, .y = y});
      add({.kind = Kind::key, .code = GLFW_KEY_O, .action = GLFW_PRESS});
      add({.kind = Kind::key, .code = GLFW_KEY_O, .action = GLFW_RELEASE});
    } else if (verb == "remove-body") {
      add({.kind = Kind::remove_body, .code = static_cast<int>(p.integer("body index", 0, 1 << 20))});
    } else if (verb == "add-ball") {
      add({.kind = Kind::add_ball});
    } else if (verb == "scroll") {
      add({.kind = Kind::scroll, .x = 0, .y = p.number("scroll amount", kMaxScroll)});
    } else if (verb == "resize") {
      const auto w = p.integer("width", 1, 16384), h = p.integer("height", 1, 16384);
      add({.kind = Kind::resize, .x = static_cast<double>(w), .y = static_cast<double>(h)});
    } else if (verb == "minimize") {
      add({.kind = Kind::minimize});
    } else if (verb == "restore") {
      add({.kind = Kind::restore});
    } else if (verb == "screenshot") {
      const std::string file = p.word("file name");
      checked_output(p, "screenshot", file);
      script.screenshots.push_back(file);
      script.screenshot_lines.push_back(number);
      add({.kind = Kind::screenshot, .screenshot = static_cast<int>(script.screenshots.size() - 1)});
    } else if (verb == "save" || verb == "load") {
      const std::string file = p.word("file name");
      if (verb == "save") checked_output(p, "save", file);
      script.checkpoints.push_back(file);
      add({.kind = verb == "save" ? Kind::save : Kind::load,
           .screenshot = static_cast<int>(script.checkpoints.size() - 1)});
    } else {
      p.fail("unknown event " + quote(verb) + " (" + kEvents + ")");
    }
    p.end();
  }
  std::stable_sort(script.events.begin(), script.events.end(),
                   [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
  return script;
}

Script load_script(const std::string& path) {
  if (path.empty()) return {};
  return parse_script(read_file(path), path);
}

}  // namespace pond::app::demo
