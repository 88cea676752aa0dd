#pragma once
/** @file
 * @brief The Legend's hatch chooser: a combo box that shows only the pattern's sample when closed (the name is in
 *        its tooltip and in the open list), so the Legend's columns fit a dock beside the 3D view in every
 *        language ("Diagonal cross" is "Αντίστροφη διαγώνια" or "Quadrillage diagonal"). Private to the library.
 */
#include <QComboBox>

namespace stylos::widgets {

class HatchBox : public QComboBox {
    Q_OBJECT

public:
    explicit HatchBox(QWidget* parent = nullptr);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    /** @brief Sets the tooltip: @p what, then the current pattern's name. */
    void setDescription(const QString& what);

protected:
    void paintEvent(QPaintEvent* event) override;
    void showPopup() override;

private:
    void refreshToolTip();

    QString m_what;
};

} // namespace stylos::widgets
