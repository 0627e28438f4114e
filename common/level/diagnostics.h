#pragma once
// Collects the problems found while reading or validating a level, each pinned to a JSON path and -- when
// the text is at hand -- to its line:column, so that loading can report every problem at once.
#include "jsonio/position_map.h"
#include "jsonio/problems.h"
#include "level/level_io.h"

#include <set>
#include <string>
#include <vector>

namespace ks::level {

// A jsonio::ProblemSink, so the shared readers (jsonio/object_reader.h) and the document checks
// (jsonio/document.h) report into a level's LoadReport like everything else.
class DiagnosticSink : public jsonio::ProblemSink {
  public:
    explicit DiagnosticSink(std::string file, const jsonio::PositionMap* positions = nullptr)
        : file_(std::move(file)), positions_(positions) {}

    void error(const std::string& path, std::string message, std::string hint = {});
    void warning(const std::string& path, std::string message, std::string hint = {});
    // An error at a known text position (syntax errors, before any path exists).
    void error_at(jsonio::TextPosition pos, const std::string& path, std::string message,
                  std::string hint = {});

    // Marks the diagnostic added last as a finding of `kind` (see Diagnostic::Kind).
    void tag_last(Diagnostic::Kind kind, std::string suggestion = {});

    void report(jsonio::Severity severity, const std::string& path, std::string message,
                std::string hint) override;
    void report_at(jsonio::Severity severity, jsonio::TextPosition pos, const std::string& path,
                   std::string message, std::string hint) override;

    // While set, every message starts with it ("robot 12 (\"Guard\"): ..."), for problems deep inside one
    // entity whose JSON path alone does not say which robot it is.
    void set_subject(std::string subject) { subject_ = std::move(subject); }
    const std::string& subject() const { return subject_; }

    bool has_errors() const;
    const std::string& file() const { return file_; }
    // Diagnostics in document order (those without a position last, in the order they were found).
    std::vector<Diagnostic> take_sorted();

  private:
    void add(Diagnostic::Severity severity, jsonio::TextPosition pos, const std::string& path,
             std::string message, std::string hint);
    std::string file_;
    const jsonio::PositionMap* positions_;
    std::vector<Diagnostic> list_;
    std::string subject_;
};

// Sets a sink's subject for the lifetime of the scope.
class SubjectScope {
  public:
    SubjectScope(DiagnosticSink& sink, std::string subject) : sink_(sink), previous_(sink.subject()) {
        sink_.set_subject(std::move(subject));
    }
    ~SubjectScope() { sink_.set_subject(previous_); }
    SubjectScope(const SubjectScope&) = delete;
    SubjectScope& operator=(const SubjectScope&) = delete;

  private:
    DiagnosticSink& sink_;
    std::string previous_;
};

// "robot 12 (\"Guard\")", or "robot 12" for an unnamed one: how messages name an entity.
std::string entity_subject(const Entity& entity);

// "entities[K]", K being the entity's index in the file (`source_index`, from the reader) where known.
std::string entity_path(size_t i, const std::vector<size_t>& source_index);

// One error holding every error-severity diagnostic of `file` (warnings are left out).
Error errors_of(const std::vector<Diagnostic>& diagnostics, const std::string& file);

// "0.01 .. 10000 units": a field's valid range as messages show it.
std::string range_text(const FieldInfo& info);

} // namespace ks::level
