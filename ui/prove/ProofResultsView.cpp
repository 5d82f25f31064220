// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/ProofResultsView.h"

#include "shell/StatusColors.h"

#include <QEvent>
#include <QHeaderView>

namespace rs::ui {

namespace {

constexpr int kLineRole = Qt::UserRole;

} // namespace

ProofResultsView::ProofResultsView(QWidget* parent) : QTreeWidget(parent) {
    setObjectName(QStringLiteral("proofResults"));
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    setAllColumnsShowFocus(true);
    setHeaderLabels({tr("Line"), tr("Property"), tr("Result"), tr("Scans"), tr("Reason")});
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(LineColumn, QHeaderView::ResizeToContents);
    header()->setSectionResizeMode(PropertyColumn, QHeaderView::Interactive);
    header()->setSectionResizeMode(ResultColumn, QHeaderView::ResizeToContents);
    header()->setSectionResizeMode(ScansColumn, QHeaderView::ResizeToContents);
    setColumnWidth(PropertyColumn, 320);
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        emit lineActivated(item->data(LineColumn, kLineRole).toInt());
    });
}

QString ProofResultsView::statusText(PropertyProof::Status status) {
    switch (status) {
    case PropertyProof::Status::Proved:
        return tr("proved");
    case PropertyProof::Status::Failed:
        return tr("failed");
    case PropertyProof::Status::Unknown:
        return tr("unknown");
    case PropertyProof::Status::Covered:
        return tr("covered");
    case PropertyProof::Status::NeverCovered:
        return tr("never covered");
    }
    return {};
}

void ProofResultsView::setProperties(const std::vector<prove::Property>& properties) {
    clear();
    m_proofs.assign(properties.size(), std::nullopt);
    for (const prove::Property& property : properties) {
        auto* item = new QTreeWidgetItem(this);
        item->setText(LineColumn, QString::number(property.line));
        item->setTextAlignment(LineColumn, Qt::AlignRight | Qt::AlignVCenter);
        item->setData(LineColumn, kLineRole, property.line);
        const QString text = QString::fromStdString(property.text).trimmed();
        item->setText(PropertyColumn, text);
        item->setToolTip(PropertyColumn, text);
        item->setText(ResultColumn, tr("waiting"));
    }
    recolour();
}

void ProofResultsView::setProving(int index) {
    if (QTreeWidgetItem* item = topLevelItem(index)) {
        item->setText(ResultColumn, tr("proving…"));
        scrollToItem(item);
    }
}

void ProofResultsView::setProof(int index, const PropertyProof& proof) {
    QTreeWidgetItem* item = topLevelItem(index);
    if (!item)
        return;
    m_proofs[static_cast<std::size_t>(index)] = proof;
    item->setText(ResultColumn, statusText(proof.status));
    item->setText(ScansColumn, QString::number(proof.depth));
    item->setTextAlignment(ScansColumn, Qt::AlignRight | Qt::AlignVCenter);
    switch (proof.status) {
    case PropertyProof::Status::Proved:
        item->setToolTip(ScansColumn,
                         tr("Proved by induction over %n scan(s)", nullptr, proof.depth));
        break;
    case PropertyProof::Status::Failed:
        item->setToolTip(ScansColumn,
                         tr("A counterexample of %n scan(s) from power on", nullptr, proof.depth));
        break;
    case PropertyProof::Status::Covered:
        item->setToolTip(ScansColumn,
                         tr("Reached in %n scan(s) from power on", nullptr, proof.depth));
        break;
    case PropertyProof::Status::Unknown:
    case PropertyProof::Status::NeverCovered:
        item->setToolTip(ScansColumn, {});
        break;
    }
    item->setText(ReasonColumn, proof.reason);
    item->setToolTip(ReasonColumn, proof.reason);
    if (!proof.scenario.isEmpty())
        item->setToolTip(ResultColumn, tr("Open Counterexample runs it in the simulator"));
    recolour();
    emit proofChanged(index);
}

void ProofResultsView::setNotProved(int index, const QString& why) {
    for (int i = index; i < topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = topLevelItem(i);
        item->setText(ResultColumn, tr("not proved"));
        item->setText(ReasonColumn, why);
    }
    recolour();
}

const PropertyProof* ProofResultsView::proofAt(int index) const {
    if (index < 0 || index >= static_cast<int>(m_proofs.size()) ||
        !m_proofs[static_cast<std::size_t>(index)])
        return nullptr;
    return &*m_proofs[static_cast<std::size_t>(index)];
}

const PropertyProof* ProofResultsView::currentProof() const {
    return proofAt(indexOfTopLevelItem(currentItem()));
}

void ProofResultsView::recolour() {
    for (int i = 0; i < topLevelItemCount(); ++i) {
        const PropertyProof* proof = proofAt(i);
        QColor color = palette().color(QPalette::PlaceholderText);
        if (proof)
            switch (proof->status) {
            case PropertyProof::Status::Proved:
            case PropertyProof::Status::Covered:
                color = passTextColor(palette());
                break;
            case PropertyProof::Status::Failed:
            case PropertyProof::Status::NeverCovered:
                color = errorTextColor(palette());
                break;
            case PropertyProof::Status::Unknown:
                color = undecidedTextColor(palette());
                break;
            }
        topLevelItem(i)->setForeground(ResultColumn, color);
    }
}

void ProofResultsView::changeEvent(QEvent* event) {
    QTreeWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        recolour();
}

} // namespace rs::ui
