#pragma once
// A QDoubleSpinBox that also reads scientific notation ("1.5e-3", "2,5E1" in French; with a point in every
// language) and a point as the decimal point where the locale writes a comma and groups with spaces (French): the
// plain spin box dropped the "e" as it was typed, so "1e12" became 112 without a word. Values are applied on Enter
// or on leaving the field only (no keyboard tracking). A number out of range stays
// Intermediate: Enter does not apply it and the box goes back to its value (Qt's CorrectToPreviousValue);
// so is a plain number out of range (the plain spin box refused the last key: 720° became 72°), and one that the
// decimals would round to the special value ("Automatic"). Group separators are never read: a point is a decimal
// point in every language (in Greek, whose group separator is the point, "1.5" was read as 15).
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
    /** @p text without the prefix and the suffix. */
    QString numberPart(const QString& text) const;
    /** The finite number @p number writes in the box's locale, or with a point for its decimal point (see the cpp). */
    std::optional<double> parse(const QString& number) const;
};

} // namespace stylos::widgets
