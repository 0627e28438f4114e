#pragma once
// ImGui 1.86 reads the keys once a frame (io.KeysDown, no input queue): a key pressed and released between
// two frames (a quick tap; xdotool's key) was never seen down, so E, Delete, Ctrl+D and the arrows were lost,
// and two taps of an arrow in one frame nudged once. Installed after ImGui's GLFW backend, this sits in
// front of its key callback and passes on only what the next frame can tell apart: a key changes once a
// frame, a release waits while any key changed this frame (else a Ctrl let go with D pressed turns Ctrl+D
// into D), and behind a waiting event everything waits, in order, for the next frame
// (release_seen_taps(), called when the frame's UI is built: the backend sets io.KeyCtrl and the others
// at once in its callback).
struct GLFWwindow;

namespace ks::shell {

void install_key_taps(GLFWwindow* window);
void uninstall_key_taps(GLFWwindow* window);
// After the frame's UI (ImGui::Render()): the frame has seen every change delivered before it; the waiting
// ones go to ImGui now, each key's next (the next frame sees them; it is asked for at once).
void release_seen_taps();

} // namespace ks::shell
