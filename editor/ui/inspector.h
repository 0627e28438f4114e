#pragma once
// The inspector (right column): the Properties tab, a list of sections (InspectorSection) each drawn when it
// applies to the selection; the Links and Objectives tabs, drawn by the window (they share the viewport's
// pick mode); and the texture browser its texture field opens. A new section: one class and one line in
// make_inspector_sections() (inspector_sections.cpp).
#include "ui/field_typing.h"
#include "ui/layout.h"
#include "ui/panel_context.h"
#include "ui/texture_browser.h"

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace ks::editor::ui {

enum class InspectorTab { Properties, Links, Objectives };
std::optional<InspectorTab> parse_inspector_tab(std::string_view name); // "properties", "links", "objectives"
const char* inspector_tab_name(InspectorTab tab);

// The texture field the selected entities share (its name) and the primary's texture.
struct SelectionTexture {
    std::string field, name;
};
std::optional<SelectionTexture> selection_texture(const Editor& editor);

// The value widgets of the inspector's fields (level settings too): one per FieldKind; the sound lists'
// names and the texture browser the texture field opens are kept here.
class FieldWidgets {
  public:
    // True when the user changed `value` this frame; `mixed`: the selected entities' values differ (grey).
    // A number typed into is changed once, when the typing ends (Enter, Tab, a click away; Esc drops it).
    bool edit(const PanelContext& ctx, const FieldDescriptor& field, FieldValue& value, bool mixed);
    // The last edit() was a typed number committed: its own undo step (nothing of a drag to merge with).
    bool typed_commit() const { return typed_commit_; }
    TextureBrowser& texture_browser() { return texture_browser_; }
    const TextureBrowser& texture_browser() const { return texture_browser_; }

  private:
    bool texture_field(const PanelContext& ctx, FieldValue& value);

    std::vector<std::string> sound_names_; // offered by the sound lists (sound_widgets.h)
    TextureBrowser texture_browser_;
    TypedEdit typed_; // numbers typed into, set when the typing ends
    bool typed_commit_ = false;
};

// What the Properties tab's sections share this frame.
struct InspectorSelection {
    std::vector<const level::Entity*> entities; // the selected entities, the primary first
    bool player_start = false;                  // the player start is selected
    float width = 0.0f;                         // the panel's width
    bool group_shown = false;                   // set by the group section when it drew
    const level::Entity& primary() const { return *entities.front(); }
};

// One section of the Properties tab. Sections are drawn in make_inspector_sections()'s order, each when
// applies() is true for the selection.
class InspectorSection {
  public:
    virtual ~InspectorSection() = default;
    virtual bool applies(const InspectorSelection& selection) const = 0;
    virtual void draw(const PanelContext& ctx, InspectorSelection& selection, FieldWidgets& widgets) = 0;
};

// The Properties tab's sections in order (inspector_sections.cpp): the one place a section is added.
std::vector<std::unique_ptr<InspectorSection>> make_inspector_sections();

class Inspector {
  public:
    Inspector();
    void draw(const PanelContext& ctx, const Rect& rect);
    // The browser window beside the inspector while its texture field has it open (closed when the
    // selection has no texture field any more); a pick is one edit.
    void texture_browser_window(const PanelContext& ctx, Vec2 position);
    void select_tab(InspectorTab tab) { select_tab_ = tab; } // brought to the front on the next frame
    InspectorTab shown_tab() const { return shown_tab_; }
    TextureBrowser& texture_browser() { return widgets_.texture_browser(); }
    const TextureBrowser& texture_browser() const { return widgets_.texture_browser(); }

  private:
    void properties_tab(const PanelContext& ctx, float width);

    std::vector<std::unique_ptr<InspectorSection>> sections_;
    FieldWidgets widgets_;
    std::optional<InspectorTab> select_tab_;
    InspectorTab shown_tab_ = InspectorTab::Properties;
};

} // namespace ks::editor::ui
