#pragma once
/** @file
 * @brief The import options of File › Import scans…: the scans' up axis (+X … −Z, turned to +Z) and length
 *        unit (mm, cm, m → metres), core::io::ImportFrame without its offset (that one is the command line's,
 *        `--offset`; the workbench's placement already moves site coordinates near the origin). Shown after the
 *        file dialog when a point file (not a `.poct`) was chosen; the choice is remembered in QSettings
 *        ("import/up", "import/unit") and is what drops and the command line's files use too. GUI thread only.
 */
#include "stylos/core/io/ImportFrame.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QSettings;

namespace stylos::widgets {

class ImportOptionsDialog : public QDialog {
    Q_OBJECT

public:
    explicit ImportOptionsDialog(const core::io::ImportFrame& frame, QWidget* parent = nullptr);

    /** @brief The chosen up axis and unit, with the offset given to the constructor. */
    core::io::ImportFrame frame() const;
    void setFrame(const core::io::ImportFrame& frame);

    /** @brief Writes the up axis and unit of @p frame under "import/". */
    static void save(QSettings& settings, const core::io::ImportFrame& frame);
    /** @brief What save() wrote; a missing or unknown value keeps its default (+Z, m). */
    static core::io::ImportFrame load(QSettings& settings);

    // For tests.
    QComboBox* upBox() const { return m_up; }
    QComboBox* unitBox() const { return m_unit; }
    QDialogButtonBox* buttons() const { return m_buttons; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    core::io::ImportFrame m_frame;
    QLabel* m_note;
    QLabel* m_upLabel;
    QLabel* m_unitLabel;
    QComboBox* m_up;
    QComboBox* m_unit;
    QDialogButtonBox* m_buttons;
};

} // namespace stylos::widgets
