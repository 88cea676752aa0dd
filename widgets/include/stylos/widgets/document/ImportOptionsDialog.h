#pragma once
/** @file
 * @brief The import options of File › Import scans…: the scans' up axis (+X … −Z, turned to +Z) and length
 *        unit (mm, cm, m → metres), and the offset subtracted first (site coordinates, in the scans' unit, as
 *        `--offset`; without it the workbench's placement still moves site coordinates near the origin):
 *        core::io::ImportFrame. Shown after the file dialog when a point file (not a `.poct`) was chosen; the
 *        choice is remembered in QSettings ("import/up", "import/unit", "import/offset") and is what drops and
 *        the command line's files use too. GUI thread only.
 */
#include "stylos/core/io/ImportFrame.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
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
    /** @brief The offset's x, y and z boxes (index 0, 1, 2). */
    QDoubleSpinBox* offsetBox(int axis) const { return m_offset[axis]; }
    QDialogButtonBox* buttons() const { return m_buttons; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    core::io::ImportFrame m_frame;
    QLabel* m_note;
    QLabel* m_upLabel;
    QLabel* m_unitLabel;
    QLabel* m_offsetLabel;
    QComboBox* m_up;
    QComboBox* m_unit;
    QDoubleSpinBox* m_offset[3];
    QDialogButtonBox* m_buttons;
};

} // namespace stylos::widgets
