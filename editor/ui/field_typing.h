#pragma once
// Number fields typed into (double-click, Ctrl+click, or Tab from the field before): ImGui 1.86 parses the
// text at every key and reports each step as a change, so "0." on the way to "0.5" was set (and refused,
// logged red) and Esc after Enter "reverted" a committed value. TypedEdit holds the typed value aside and
// hands it on once, when the typing ends: Enter, Tab or a click elsewhere commit it, Esc drops it. Dragging
// the number (no typing) passes through, a change each frame, as before.
#include "model/field_access.h"

#include <imgui.h>

#include <unordered_map>
#include <vector>

namespace ks::editor::ui {

class TypedEdit {
  public:
    // Right after the widget whose id (ImGui::GetID of its label, taken before it) is `widget`, with what
    // it returned and the value it left; `target`: what the edit applies to (the selection), so a value
    // typed for one entity is never committed to the next one selected. True when `value` is to be set now
    // (the typed value on commit, or a drag's value).
    bool filter(ImGuiID widget, const std::vector<int>& target, bool changed, FieldValue& value);
    // The widget is being typed into (for its hint).
    bool typing(ImGuiID widget) const { return typed_.contains(widget) && typing_now(); }

  private:
    static bool typing_now(); // the active item is a number field's text input

    struct Typed {
        ImGuiID component = 0; // the item typed into (one of a vector's numbers)
        bool has_value = false;
        FieldValue value;
        std::vector<int> target;
        int frame = 0; // when the widget was last drawn: an older entry is stale
    };
    // By widget: Tab to the next field activates it before the one left is drawn again, so two can be
    // waiting at once.
    std::unordered_map<ImGuiID, Typed> typed_;
};

// The bounds a float widget may clamp to: the nearest floats inside [min, max] (a float 0.01 is below the
// double 0.01 and was refused as out of range).
float float_at_least(double min);
float float_at_most(double max);

// "Enter or Tab sets it, Esc cancels" and the field's range, under a field being typed into.
void typing_hint(const FieldDescriptor& field);

} // namespace ks::editor::ui
