#pragma once
/** @file
 * @brief Undo command: replaces the plate kept in the project (the settings of the last File › Export plate…),
 *        so the figure can be made again later. GUI thread only.
 */
#include "document/commands/DocumentCommand.h"
#include "stylos/core/plate/PlateSpec.h"

#include <optional>

namespace stylos::widgets {

class SceneDocument;

class SetPlateCommand : public DocumentCommand {
public:
    SetPlateCommand(SceneDocument& document, std::optional<core::plate::PlateSpec> plate, const CommandText& text,
                    QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    std::optional<core::plate::PlateSpec> m_old;
    std::optional<core::plate::PlateSpec> m_new;
};

} // namespace stylos::widgets
