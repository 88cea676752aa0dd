#pragma once
/** @file
 * @brief The contact readout in the Properties dock: for the selected fragment against the docking drum's guides
 *        (ContactMonitor), the largest interpenetration, the median, 90 % and 99 % gaps (millimetres; negative:
 *        inside the drum), the share of the outer face within 0.5 mm and the points measured; a line says when
 *        there is nothing to show (no docking drum, computing, no contact, a failure); then, against each other
 *        fragment of its assembly, the largest interpenetration, the median and 90 % gaps and the points measured.
 *        GUI thread only.
 */
#include <QWidget>

#include <array>

class QLabel;
class QFormLayout;

namespace stylos::widgets {

class ContactMonitor;

class ContactReadoutWidget : public QWidget {
    Q_OBJECT

public:
    /** Shows @p monitor (not owned; it must outlive the widget). */
    explicit ContactReadoutWidget(ContactMonitor& monitor, QWidget* parent = nullptr);

    // The fields, for tests.
    QLabel* statusLabel() const { return m_status; }
    QLabel* interpenetrationLabel() const { return m_values[0]; }
    QLabel* medianLabel() const { return m_values[1]; }
    QLabel* gap90Label() const { return m_values[2]; }
    QLabel* gap99Label() const { return m_values[3]; }
    QLabel* withinLabel() const { return m_values[4]; }
    QLabel* pointsLabel() const { return m_values[5]; }
    /** The contact with the other fragments of the assembly, a line each (empty when none). */
    QLabel* membersLabel() const { return m_members; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void refresh();

    static constexpr std::size_t Rows = 6;
    ContactMonitor& m_monitor;
    QFormLayout* m_form;
    QLabel* m_status;
    QLabel* m_members;
    std::array<QLabel*, Rows> m_labels{};
    std::array<QLabel*, Rows> m_values{};
};

} // namespace stylos::widgets
