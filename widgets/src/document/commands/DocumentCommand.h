#pragma once
/** @file
 * @brief The base of the document's undo commands: a QUndoCommand whose text follows the language
 *        (CommandText), made again by retranslate(). GUI thread only.
 */
#include "stylos/widgets/document/CommandText.h"

#include <QUndoCommand>

namespace stylos::widgets {

class DocumentCommand : public QUndoCommand {
public:
    using QUndoCommand::QUndoCommand;

    /** @brief Keeps @p text and shows it in the current language. */
    void setText(CommandText text)
    {
        m_text = std::move(text);
        QUndoCommand::setText(m_text.text());
    }
    /** @brief Makes the text again in the current language. */
    void retranslate() { QUndoCommand::setText(m_text.text()); }

private:
    CommandText m_text;
};

} // namespace stylos::widgets
