// killswitch: the game runtime.
#include "core/cli.h"
#include "core/log.h"
#include "render/app_shell.h"

#include <imgui.h>

#include <cstdio>

namespace {
const std::vector<std::string> kFlags = {"no-vsync", "help"};

void print_help() {
    std::printf("usage: killswitch [--level FILE] [--width W] [--height H] [--screenshot FILE --frames N]\n");
}
} // namespace

int main(int argc, char** argv) {
    auto cl = ks::CommandLine::parse(argc, argv, kFlags);
    if (!cl) {
        ks::log::error(cl.error().str());
        return 2;
    }
    if (cl->has("help")) {
        print_help();
        return 0;
    }
    std::vector<std::string> known = ks::render::shell_options();
    known.insert(known.end(), {"level", "help"});
    if (auto unknown = cl->unknown(known); !unknown.empty()) {
        ks::log::error("unknown option ", unknown.front(), " (see killswitch --help)");
        return 2;
    }
    auto config = ks::render::shell_config_from_command_line(*cl, {});
    if (!config) {
        ks::log::error(config.error().str());
        return 2;
    }
    if (!ks::render::display_available()) {
        std::fprintf(stderr, "%s\n", ks::render::no_display_message("killswitch").c_str());
        return 3;
    }
    auto shell = ks::render::AppShell::create(*config);
    if (!shell) {
        ks::log::error(shell.error().str());
        return 1;
    }
    ks::render::ShellHooks hooks;
    hooks.imgui = [&](const ks::render::FrameInfo& info) {
        ImGui::SetNextWindowPos(ImVec2(info.width * 0.5f, info.height * 0.4f), 0, ImVec2(0.5f, 0.5f));
        ImGui::Begin("title", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                           ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::PushFont((*shell)->fonts().title);
        ImGui::TextColored(ImVec4(0.95f, 0.75f, 0.2f, 1), "KILLSWITCH");
        ImGui::PopFont();
        ImGui::Text("OpenGL: %s", (*shell)->gl_renderer().c_str());
        ImGui::End();
    };
    int code = (*shell)->run(hooks);
    ks::render::AppShell::destroy(*shell);
    return code;
}
