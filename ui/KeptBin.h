#pragma once
// The kept bin: materials the user picked from runs, with names. They are part of the preset
// (saved with it, undoable) and survive re-runs, new seeds and family changes; variant sets and
// exports start from them. Tiles are selected with a click, several with Ctrl+click, and kept
// with "Keep" or K.
#include <vector>

#include "EditorState.h"

namespace matevo::ui {

// Adds the genomes not yet in the bin, named "<preset name> <n>", evolved in the preset's
// current family; returns how many were added.
int keepMaterials(Preset& preset, const std::vector<Genome>& genomes);

// "Keep" (button or K): the tiles marked with Ctrl+click, else the inspected candidate, go into
// the bin; the status bar says what happened.
void keepPicked(EditorState& state);

// The bin's tab: "Export set…", then a tile per kept material with its name (editable), ΔE00
// from the current target when it was drawn, and a remove button. True when "Export set…" was
// clicked.
bool drawKeptBin(EditorState& state);

}  // namespace matevo::ui
