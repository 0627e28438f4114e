#pragma once
// ImGui 1.86 reads the keys once a frame (io.KeysDown, no input queue): a key pressed and released between
// two frames (a quick tap; xdotool's key) was never seen down, so E, Delete, Ctrl+D and the arrows were lost.
// Installed after ImGui's GLFW backend, this sits in front of its key callback and holds such a release back
// until a frame has seen the key down (release_seen_taps(), called when the frame's UI is built: the backend
// sets io.KeyCtrl and the others at once in its callback, so a Ctrl let go earlier would turn a Ctrl+D
// tap into a D).
struct GLFWwindow;

namespace ks::shell {

void install_key_taps(GLFWwindow* window);
void uninstall_key_taps(GLFWwindow* window);
// After the frame's UI (ImGui::Render()): the frame has seen every key pressed before it; the releases
// held back go to ImGui now (it sees them on the next frame, which is asked for at once).
void release_seen_taps();

} // namespace ks::shell
