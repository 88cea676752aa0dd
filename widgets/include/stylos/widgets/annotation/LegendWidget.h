#pragma once
/** @file
 * @brief The Legend dock's contents: both annotation layers' classes (colour swatch, name, hatch, cells, area in
 *        m² from ClassMeasures), the active class (a click chooses it: classChosen()), and the edits — rename (edit
 *        the name in place), recolour (Colour…, QColorDialog), change the hatch (its list), add a class, delete a
 *        class. Deleting a used class asks what becomes of its cells (unlabelled, or moved to another class of the
 *        layer), saying how many there are (LabelStore::count). Every edit is one undo step of the document.
 *        Default names are shown translated (LegendText); a name is stored as typed. GUI thread only.
 */
#include "stylos/core/annotation/Legend.h"

#include <QColor>
#include <QWidget>

#include <functional>
#include <optional>

class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace stylos::widgets {

class ClassMeasures;
class SceneDocument;

class LegendWidget : public QWidget {
    Q_OBJECT

public:
    using AnnotationLayer = core::annotation::AnnotationLayer;
    /** Asked when a used class is deleted: the replacement id (0: unlabel), or nullopt to keep the class. */
    using RemovalChooser = std::function<std::optional<std::uint8_t>(AnnotationLayer layer, std::uint8_t classId,
                                                                    std::uint64_t cells)>;

    /** @p measures may be null (no cells or areas shown). Neither owned. */
    LegendWidget(SceneDocument& document, ClassMeasures* measures, QWidget* parent = nullptr);

    QTreeWidget* tree() const { return m_tree; }
    /** @brief The row of class @p classId of @p layer; nullptr when there is none. */
    QTreeWidgetItem* itemOf(AnnotationLayer layer, std::uint8_t classId) const;

    // The edits (each one undo step; false when nothing changed).
    bool renameClass(AnnotationLayer layer, std::uint8_t classId, const QString& name);
    bool setClassColour(AnnotationLayer layer, std::uint8_t classId, const QColor& colour);
    bool setClassHatch(AnnotationLayer layer, std::uint8_t classId, core::annotation::Hatch hatch);
    /** @brief Adds a class to @p layer (the smallest free id, an unused colour); returns its id, 0 when full. */
    std::uint8_t addClass(AnnotationLayer layer);
    /** @brief Deletes the class, asking the chooser (a dialog by default) when cells hold it. */
    bool removeClass(AnnotationLayer layer, std::uint8_t classId);
    void setRemovalChooser(RemovalChooser chooser) { m_chooser = std::move(chooser); }

    /** @brief Selects the row of the active class (no classChosen()). */
    void showActive(AnnotationLayer layer, std::uint8_t classId);

    void retranslateUi();

Q_SIGNALS:
    /** @brief The user chose the class to paint. */
    void classChosen(stylos::core::annotation::AnnotationLayer layer, std::uint8_t classId);

protected:
    void changeEvent(QEvent* event) override;

private:
    void rebuild();
    void refreshMeasures();
    /** The tree as wide as its columns need (header and values, the vertical scroll bar), so the dock shows
     *  every column in every language instead of scrolling the area out of sight. */
    void fitColumns();
    std::optional<std::pair<AnnotationLayer, std::uint8_t>> currentClass() const;
    core::annotation::LegendClass* editable(core::annotation::Legend& legend, AnnotationLayer layer, std::uint8_t id) const;
    std::optional<std::uint8_t> askReplacement(AnnotationLayer layer, std::uint8_t classId, std::uint64_t cells);
    void updateButtons();

    SceneDocument& m_document;
    ClassMeasures* m_measures;
    QTreeWidget* m_tree;
    QPushButton* m_add;
    QPushButton* m_colour;
    QPushButton* m_remove;
    RemovalChooser m_chooser;
    bool m_updating = false;
    int m_editing = 0; ///< inside a row's or a hatch list's own signal
    std::optional<std::pair<AnnotationLayer, std::uint8_t>> m_active;
};

} // namespace stylos::widgets
