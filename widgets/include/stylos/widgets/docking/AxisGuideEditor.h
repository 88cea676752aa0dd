#pragma once
/** @file
 * @brief Axis guides made in the workbench: "Set axis from two points" installs an AxisPickTool on the 3D view for
 *        a fragment, and the two points it hands back become the fragment's axis guide (through them, from the
 *        first to the second, in its own frame); "Edit axis…" opens an EditAxisDialog on the fragment's axis guide
 *        (or a vertical one through its origin); "Reverse axis" turns it end for end. Each replaces the fragment's first Axis guide (its flute guides
 *        kept), or adds one in front, as one undo step (SceneDocument::setFragmentGuides). GUI thread only.
 */
#include "stylos/core/scene/Fragment.h"
#include "stylos/widgets/document/SceneDocument.h"

#include <Eigen/Core>

#include <QObject>
#include <QPointer>
#include <QString>

#include <vector>

class QWidget;

namespace stylos::widgets {

class AxisPickTool;
class EditAxisDialog;
class ViewportWidget;

class AxisGuideEditor : public QObject {
    Q_OBJECT

public:
    using FragmentId = SceneDocument::FragmentId;

    /** None owned; @p view may be null (no OpenGL: no picking). */
    AxisGuideEditor(SceneDocument& document, ViewportWidget* view, QObject* parent = nullptr);

    /** @brief @p guides with the axis through @p origin along @p direction (unit, own frame) as its first Axis guide. */
    static std::vector<core::scene::Guide> withAxis(std::vector<core::scene::Guide> guides, const Eigen::Vector3d& origin,
                                                    const Eigen::Vector3d& direction);
    /** @brief Sets the axis guide of @p id (own frame; @p direction of any non-zero length) as one undo step; false
     *         (nothing changed) for a zero direction, an unknown fragment or the same axis. */
    bool setAxis(FragmentId id, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const QString& commandText);

    /** @brief Starts picking two points on @p id in the 3D view; false without a view or fragment. */
    bool startPicking(FragmentId id);
    /** @brief True while the pick tool is the view's tool. */
    bool isPicking() const;
    /** @brief Gives the view back to navigation (as Escape does). */
    void cancelPicking();

    /** @brief Turns @p id's axis guide end for end (the same line, the opposite direction) as one undo step: a drum
     *         whose fitted axis points down (one lying on its side, where nothing in a cylinder tells up from down)
     *         then unrolls the right way up. False (nothing changed) without an axis guide. */
    bool reverseAxis(FragmentId id);

    /** @brief Opens the dialog for @p id's axis (not modal; OK sets it); null for an unknown fragment. */
    EditAxisDialog* editAxis(FragmentId id, QWidget* parent);

Q_SIGNALS:
    /** @brief A message for the log; @p failed: a problem. */
    void reported(const QString& message, bool failed);
    void pickingChanged(bool picking);

private:
    void picked(FragmentId id, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
    /** Gives the view back to navigation on the next turn (the tool is in its own handler now). */
    void endPickingLater();

    SceneDocument& m_document;
    QPointer<ViewportWidget> m_view;
    AxisPickTool* m_tool = nullptr; ///< owned by the view while installed
};

} // namespace stylos::widgets
