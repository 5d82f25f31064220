// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QCompleter;
class QLabel;
class QLineEdit;
class QToolButton;

namespace rs::ui {

class SimulationSession;
class WaveformView;

// The Waveform dock: the plot, the variables to record (added by name or
// address, removed when chosen), zoom, and export of the recording as VCD.
class WaveformPanel : public QWidget {
    Q_OBJECT
public:
    explicit WaveformPanel(SimulationSession* session, QWidget* parent = nullptr);

    WaveformView* view() const { return m_view; }
    // Records the variable from now on; the reason when it cannot.
    QString add(const QString& word);
    // Stops plotting every variable.
    void removeAll();
    // Writes the recording; the error message, empty on success. Without a path, asks for one.
    QString exportVcd(const QString& path = {});

private:
    SimulationSession* m_session;
    WaveformView* m_view;
    QLineEdit* m_input;
    QCompleter* m_completer;
    QLabel* m_message;
    QToolButton* m_remove;
};

} // namespace rs::ui
