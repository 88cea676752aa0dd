#pragma once
/** @file
 * @brief The text of an undo step, made again in the current language when the language changes: either a
 *        fixed text, or a function that translates it ("Move %1" with the fragment's current name). The
 *        document's steps keep one (SceneDocument::retranslate()), so the Edit menu and the undo history read
 *        in the language chosen last, not the one a step was made in. GUI thread only.
 */
#include <QString>

#include <concepts>
#include <functional>
#include <utility>

namespace stylos::widgets {

class CommandText {
public:
    CommandText() = default;
    /** A text that stays as it is (a name the user typed, a text made elsewhere). */
    CommandText(QString fixed) : m_fixed(std::move(fixed)) {} // NOLINT: implicit on purpose
    CommandText(const char*) = delete;                        // a literal would never be translated
    /** A text made by @p make (which calls tr()) now and after every change of language. */
    template <typename F>
        requires std::invocable<F&> && std::convertible_to<std::invoke_result_t<F&>, QString>
    CommandText(F make) : m_make(std::move(make)) // NOLINT: implicit on purpose
    {
    }

    QString text() const { return m_make ? m_make() : m_fixed; }
    bool isEmpty() const { return !m_make && m_fixed.isEmpty(); }

private:
    QString m_fixed;
    std::function<QString()> m_make;
};

} // namespace stylos::widgets
