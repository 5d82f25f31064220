// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ProofRun.h"

#include <QTreeWidget>

#include <optional>
#include <vector>

namespace rs::ui {

// Prove All's results below the properties' text: a row per property with
// its line, its text, what was found (proved, failed, unknown, covered,
// never covered) in the status colours, the scans it took and why it is
// unknown. Double-clicking a row asks to show its line.
class ProofResultsView : public QTreeWidget {
    Q_OBJECT
public:
    enum Column { LineColumn, PropertyColumn, ResultColumn, ScansColumn, ReasonColumn };

    explicit ProofResultsView(QWidget* parent = nullptr);

    // A row for each property, waiting to be proved.
    void setProperties(const std::vector<prove::Property>& properties);
    void setProving(int index);
    void setProof(int index, const PropertyProof& proof);
    // The rows from `index` on were not proved: the run was cancelled or could not start.
    void setNotProved(int index, const QString& why);
    // The proof of the current row, if it has one.
    const PropertyProof* currentProof() const;
    const PropertyProof* proofAt(int index) const;

    static QString statusText(PropertyProof::Status status);

signals:
    void lineActivated(int line);
    // Row `index` has its proof now.
    void proofChanged(int index);

protected:
    void changeEvent(QEvent* event) override;

private:
    void recolour();

    std::vector<std::optional<PropertyProof>> m_proofs;
};

} // namespace rs::ui
