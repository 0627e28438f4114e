// killswitch-editor: the level editor.
#include "core/cli.h"
#include "core/log.h"
#include "render/app_shell.h"

#include <imgui.h>

#include <cstdio>

int main(int argc, char** argv) {
    auto cl = ks::CommandLine::parse(argc, argv, {"no-vsync", "help"});
    if (!cl) {
        ks::log::error(cl.error().str());
        return 2;
    }
    if (cl->has("help")) {
        std::printf("usage: killswitch-editor [--level FILE] [--screenshot FILE --frames N]\n");
        return 0;
    }
    ks::render::ShellConfig defaults;
    defaults.title = "Killswitch Editor";
    auto config = ks::render::shell_config_from_command_line(*cl, defaults);
    if (!config) {
        ks::log::error(config.error().str());
        return 2;
    }
    if (!ks::render::display_available()) {
        std::fprintf(stderr, "%s\n", ks::render::no_display_message("killswitch-editor").c_str());
        return 3;
    }
    auto shell = ks::render::AppShell::create(*config);
    if (!shell) {
        ks::log::error(shell.error().str());
        return 1;
    }
    int code = (*shell)->run({});
    ks::render::AppShell::destroy(*shell);
    return code;
}
