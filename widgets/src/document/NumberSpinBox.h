#pragma once
// A QDoubleSpinBox that also reads scientific notation ("1.5e-3", "2,5E1" in French): the plain spin box
// drops the "e" as it is typed, so "1e12" became 112 without a word. A number out of range stays
// Intermediate: Enter does not apply it and the box goes back to its value (Qt's CorrectToPreviousValue);
// so is a plain number out of range (the plain spin box refused the last key: 720° became 72°).
#include <QDoubleSpinBox>

#include <optional>

namespace stylos::widgets {

class NumberSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    /** The wheel steps it only once it has the focus (guardWheel). */
    explicit NumberSpinBox(QWidget* parent = nullptr);

protected:
    QValidator::State validate(QString& text, int& pos) const override;
    double valueFromText(const QString& text) const override;

private:
    /** The number in @p text without prefix and suffix, if it is written with an exponent. */
    std::optional<double> scientific(const QString& text, bool* partial) const;
};

} // namespace stylos::widgets
