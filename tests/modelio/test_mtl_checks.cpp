// An OBJ's material library checked before assimp reads it (modelio/mtl_checks.h): assimp 5.2.5's MTL
// reader writes a texture or anisotropy statement into the current material without checking there is
// one, and crashes when the statement comes before the file's first newmtl. The check is held against
// assimp itself: each library is read by assimp in a child process, and it crashes exactly when the
// check refuses.
#include "modelio/model_import.h"
#include "modelio/mtl_checks.h"
#include "test_support.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

using namespace ks;

namespace {

const std::filesystem::path kLibrary = "props/crate.mtl";
const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

std::string mtl_refusal(const std::string& text, bool material_current = false) {
    const auto r = modelio::check_mtl_file(text, kLibrary, material_current);
    return r.ok() ? std::string() : r.error().str();
}

// Whether assimp, reading `obj` (which names the library), dies: in a child, so a crash is an answer.
bool assimp_crashes_on(const std::filesystem::path& obj) {
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        // The test runner's (and ASan's) crash handlers belong to the parent: here a crash is the answer.
        for (int signal : {SIGSEGV, SIGBUS, SIGABRT, SIGILL, SIGFPE}) std::signal(signal, SIG_DFL);
        (void)std::freopen("/dev/null", "w", stdout);
        (void)std::freopen("/dev/null", "w", stderr);
        Assimp::Importer importer;
        importer.ReadFile(obj.string(), 0);
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

} // namespace

TEST_CASE("mtl checks: a texture or anisotropy before the first newmtl is refused with its place") {
    CHECK(mtl_refusal("map_Kd crate.png\nnewmtl wood\n").find("crate.mtl:1:1: \"map_Kd\" comes before") !=
          std::string::npos);
    CHECK(mtl_refusal("# exported\n\n  bump crate_n.png\n").find("crate.mtl:3:3: \"bump\"") != std::string::npos);
    CHECK(mtl_refusal("Kd 1 1 1\r\ndisp h.png\r\n").find(":2:1: \"disp\"") != std::string::npos);
    CHECK(mtl_refusal("Ns 10\nnorm n.png\n").find(":2:1:") != std::string::npos);
    CHECK(mtl_refusal("a 0.5\n\n\n").find("newmtl <name>") != std::string::npos);
    CHECK_FALSE(mtl_refusal("map_pr r.png\n").empty()); // the reader compares keywords ignoring case
    // Statements the reader reads without a material, or does not dispatch.
    CHECK(
        modelio::check_mtl_file("Kd 1 1 1\nKa 0 0 0\nd 0.5\nTr 0.1\nNs 3\nillum 2\nrefl -type sphere r.png\n"
                                "map_unknown x\nMAP_KD x.png\n",
                                kLibrary, false)
            .ok());
    CHECK(modelio::check_mtl_file("  map_Kd x.png\nnewmtl a\n", kLibrary, false)
              .ok()); // the first line is skipped
    // After a material: everything passes, and the answer says a material is current.
    const auto after =
        modelio::check_mtl_file("newmtl wood\nmap_Kd -bm 2 crate.png\na 0.2\n", kLibrary, false);
    REQUIRE(after.ok());
    CHECK(*after);
    CHECK(*modelio::check_mtl_file("map_Kd crate.png\n", kLibrary, true));
    CHECK_FALSE(*modelio::check_mtl_file("Kd 1 1 1\n", kLibrary, false));
    CHECK(*modelio::check_mtl_file("Newmtl x\nbump b.png\n", kLibrary, false)); // 'N' then 'e' makes one
    // What the reader's text conversion does first: a file under 8 bytes is refused by the reader itself, a
    // UTF-8 byte order mark is dropped, UTF-16 and UTF-32 are refused here (the reader parses raw bytes).
    CHECK(modelio::check_mtl_file("a 0.5\n", kLibrary, false).ok());
    CHECK(mtl_refusal("\xEF\xBB\xBFmap_Kd x.png\n").find("crate.mtl:1:4: \"map_Kd\"") != std::string::npos);
    for (const std::string& bom : {std::string("\xFE\xFF"), std::string("\xFF\xFE"),
                                   std::string("\0\0\xFE\xFF", 4), std::string("\xFF\xFE\0\0", 4)}) {
        CAPTURE(bom.size());
        CHECK(mtl_refusal(bom + "newmtl a\nKd 1 1 1\n")
                  .find("crate.mtl:1:1: the material library is UTF-16 or UTF-32") != std::string::npos);
    }
}

TEST_CASE("mtl checks: assimp crashes on a library exactly when the check refuses it") {
    test::ScratchDir dir;
    const std::vector<std::string> libraries{"map_Kd crate.png\nnewmtl wood\n",
                                             "newmtl wood\nmap_Kd crate.png\n",
                                             "bump b.png\n",
                                             "disp d.png\n",
                                             "norm n.png\n",
                                             "a 0.5\n# anisotropy first\n",
                                             "a\n\n\n\n\n\n\n",
                                             "a 0.5\n", // under 8 bytes: the reader refuses the file first
                                             "refl r.png\n",
                                             "map_unknown u.png\n",
                                             "MAP_KD k.png\n",
                                             "  map_Kd x.png\n",
                                             "Kd 1 1 1\n\t map_Ks s.png\n",
                                             "Kd 1 1 1\r\nmap_d o.png\r\n",
                                             "dispose\n",
                                             "nope n\n",
                                             "Ne\nmap_Kd k.png\n",
                                             "map_Pm -bm 2 m.png\n",
                                             "",
                                             "# only a comment\n",
                                             "\xEF\xBB\xBFmap_Kd x.png\n",
                                             "\xEF\xBB\xBF  map_Kd x.png\n"};
    int crashes = 0;
    for (std::size_t i = 0; i < libraries.size(); ++i) {
        CAPTURE(libraries[i]);
        const auto obj = test::write_file(dir / ("m" + std::to_string(i) + ".obj"),
                                          "mtllib lib" + std::to_string(i) + ".mtl\n" + kTriangle);
        const auto library = test::write_file(dir / ("lib" + std::to_string(i) + ".mtl"), libraries[i]);
        const bool refused = !modelio::check_mtl_file(libraries[i], library, false).ok();
        const bool crashed = assimp_crashes_on(obj);
        CHECK(refused == crashed);
        crashes += crashed ? 1 : 0;
    }
    CHECK(crashes == 11);
}

TEST_CASE("mtl checks: the import reads the library the reader would, knowing a usemtl before it") {
    test::ScratchDir dir;
    test::write_file(dir / "crate.mtl", "map_Kd crate.png\nnewmtl wood\nKd 0.5 0.3 0.1\n");
    const auto named = test::write_file(dir / "named.obj", "mtllib crate.mtl\nusemtl wood\n" + kTriangle);
    auto model = modelio::import_model(named, modelio::ImportLimits{});
    REQUIRE_FALSE(model.ok());
    CHECK(model.error().where.file == (dir / "crate.mtl").string());
    CHECK(model.error().where.line == 1);
    CHECK(model.error().message.find(
              "in named.obj's material library: \"map_Kd\" comes before the file's first "
              "newmtl") != std::string::npos);
    // A usemtl first makes a material current: the reader writes the texture there, and the import goes on
    // (to the missing texture, which it names).
    const auto used = test::write_file(dir / "used.obj", "usemtl wood\nmtllib crate.mtl\n" + kTriangle);
    auto used_model = modelio::import_model(used, modelio::ImportLimits{});
    if (!used_model.ok()) CHECK(used_model.error().message.find("newmtl") == std::string::npos);
    // A library that is not there falls back to the OBJ's own name with .mtl.
    test::write_file(dir / "fallback.mtl", "bump b.png\n");
    const auto fallback = test::write_file(dir / "fallback.obj", "mtllib missing.mtl\n" + kTriangle);
    auto fallback_model = modelio::import_model(fallback, modelio::ImportLimits{});
    REQUIRE_FALSE(fallback_model.ok());
    CHECK(fallback_model.error().where.file == (dir / "fallback.mtl").string());
    // No library at all: the import goes on.
    const auto none = test::write_file(dir / "none.obj", "mtllib nowhere.mtl\n" + kTriangle);
    CHECK(modelio::import_model(none, modelio::ImportLimits{}).ok());
}
