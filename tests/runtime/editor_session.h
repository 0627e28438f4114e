#pragma once
// The editor window driven by real X input in tests (xdotool under Xvfb): killswitch-editor as a child
// process on a display of the test's own, and a session that reads its --status-file, waits on the state
// an input should produce (never on time), and sends keys and clicks at places the status names.
#include "runtime/play_session.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <sys/types.h>
#include <vector>

namespace ks::test {

// The editor as a child process, killed when the test ends.
class EditorProcess {
  public:
    EditorProcess(const std::vector<std::string>& args, std::vector<std::string> env,
                  const PrivateDisplay& display);
    ~EditorProcess();
    EditorProcess(const EditorProcess&) = delete;
    EditorProcess& operator=(const EditorProcess&) = delete;
    bool alive() const;
    pid_t pid() const { return pid_; }
    // Waits up to `seconds` for the editor to exit by itself; its exit code, or -1 if it did not.
    int wait_exit(double seconds);

  private:
    pid_t pid_ = -1;
};

class EditorSession {
  public:
    using json = nlohmann::json;
    EditorSession(std::filesystem::path status, const EditorProcess& process, const PrivateDisplay& display);

    // Waits (up to 90 s: frames take a quarter second under llvmpipe on a busy machine) until `ready`
    // accepts the status; fails with the last status otherwise.
    json wait(const char* what, const std::function<bool(const json&)>& ready);
    // Waits until the editor has drawn `n` more frames (so it has seen the input sent before). Counted from
    // the status as it is now, not from the last one read: that one can be many frames old (xdotool calls
    // take time), and counting from it let a key's release follow its press within one frame, which ImGui
    // 1.86 (no input queue) never sees.
    json frames(int n);
    // Window coordinates from the status to screen coordinates for xdotool.
    std::string at(const json& point) const;
    // Keys go to the focused window; with no window manager under Xvfb, focus the editor's first. ImGui
    // 1.86 samples key state once per frame (no input queue), so the key is held until a frame has seen it
    // (the status's input.keys_down) and released before the key repeat starts.
    void key(const std::string& keys, std::chrono::milliseconds hold = std::chrono::milliseconds(0));
    // Types text into the focused text field, then waits two frames.
    void type(const std::string& text);
    // Gives the editor's window the keyboard focus (no window manager under Xvfb does it) and waits until
    // the X server has done so.
    void focus();
    // Moves the pointer to `point` (window coordinates) and waits until a frame has seen it there.
    void move_to(const json& point);
    // Moves the pointer to `point` (window coordinates), waits until the editor has seen it there, then
    // clicks.
    void click(const json& point);
    // A left-button drag from `from` by (dx, dy) pixels in `steps` moves, each seen by the editor before the
    // next (ImGui 1.86 polls the pointer once a frame: a move and the release in one frame lose the move).
    void drag(const json& from, float dx, float dy, int steps = 4);
    // The left button pressed (released) where the pointer is, once a frame has seen it so.
    void press();
    void release();
    std::string xdo(const std::string& args, int timeout_s = 30) const;
    const json& last() const { return last_; }

  private:
    std::filesystem::path status_;
    const EditorProcess& process_;
    std::string display_;
    std::string window_;
    json last_;
};

// Fails the test unless there is a display and xdotool (./run.sh test provides both: their absence is a
// failure, not a skip).
void require_window_test_tools();
// The status names the widget spot `name` (its "spots" object).
bool has_spot(const nlohmann::json& status, const std::string& name);

// The editor in a window on a display of its own, with a scratch folder for what it reads and writes: the
// status file and the editor's config and data folders (so no test sees another's recent files or prefabs).
class ScratchEditor {
  public:
    EditorSession& session() { return *session_; }
    EditorProcess& process() { return *process_; }
    const ScratchDir& dir() const { return dir_; }

  protected:
    ScratchEditor(); // fails the test without a display and xdotool
    // Starts the editor with `args` and "--status-file FILE".
    void start(std::vector<std::string> args);
    ScratchDir dir_;

  private:
    PrivateDisplay display_;
    std::unique_ptr<EditorProcess> process_;
    std::unique_ptr<EditorSession> session_;
};

// The editor opened on a level of the test's own: the level is written to `level_file` in the scratch
// folder. `args` follow "--level FILE".
class EditorWindow : public ScratchEditor {
  public:
    EditorWindow(const std::string& level_json, const std::vector<std::string>& args);
    const std::filesystem::path& level_file() const { return level_file_; }

  private:
    std::filesystem::path level_file_;
};

// The editor's Dojo tab on a scratch copy of the shipped clip file (assets/animations/robot.json) at
// 1280×720; `view` is a --dojo-view spec (empty: none).
class DojoWindow : public ScratchEditor {
  public:
    explicit DojoWindow(const std::string& view = "");
    const std::filesystem::path& clips() const { return clips_; }

  private:
    std::filesystem::path clips_;
};

} // namespace ks::test
