#pragma once
/** @file
 * @brief Undo command: replaces the project's annotation legend (a class renamed, recoloured, given another
 *        hatch, added or removed). Removing a class that leaves hold is a macro: the leaves' relabelling
 *        (EditLabelsCommand per fragment) then this. GUI thread only.
 */
#include "document/commands/DocumentCommand.h"
#include "stylos/core/annotation/Legend.h"

namespace stylos::widgets {

class SceneDocument;

class SetLegendCommand : public DocumentCommand {
public:
    SetLegendCommand(SceneDocument& document, core::annotation::Legend legend, const CommandText& text,
                     QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    core::annotation::Legend m_old;
    core::annotation::Legend m_new;
};

} // namespace stylos::widgets
