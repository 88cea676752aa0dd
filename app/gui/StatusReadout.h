#pragma once
/** @file
 * @brief The status bar's permanent readouts of the 3D view: the 3D coordinate under the cursor
 *        (scene frame, metres, to the millimetre) and the frame rate with the points drawn in the last
 *        frame. GUI thread only.
 */
#include <QWidget>

#include <Eigen/Core>

class QLabel;

namespace stylos::app {

class StatusReadout : public QWidget {
    Q_OBJECT

public:
    explicit StatusReadout(QWidget* parent = nullptr);

    void setCursor3d(const Eigen::Vector3d& point);
    void setFrameTime(double ms);
    void setPointsDrawn(quint64 points);

    QString cursorText() const;
    QString frameText() const;

    /** @brief "x 1.234  y −0.500  z 2.000 m". */
    static QString formatPoint(const Eigen::Vector3d& point);
    /** @brief "20 fps · 50.0 ms · 1.25 M points". */
    static QString formatFrame(double ms, quint64 points);

protected:
    void changeEvent(QEvent* event) override;

private:
    void refreshFrame();

    QLabel* m_cursor;
    QLabel* m_frame;
    double m_ms = 0;
    quint64 m_points = 0;
};

} // namespace stylos::app
