// edit_primitive_factory.h: registers the Primitive Edit tool with MeshLab (one toolbar/Edit menu action).
#ifndef PRIMITIVE_EDIT_EDIT_PRIMITIVE_FACTORY_H
#define PRIMITIVE_EDIT_EDIT_PRIMITIVE_FACTORY_H

#include <common/interfaces.h>

class EditPrimitiveFactory : public QObject, public MeshEditInterfaceFactory
{
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_EDIT_INTERFACE_FACTORY_IID)
  Q_INTERFACES(MeshEditInterfaceFactory)

public:
  EditPrimitiveFactory();
  ~EditPrimitiveFactory() override = default;

  QList<QAction*> actions() const override;
  MeshEditInterface* getMeshEditInterface(QAction* action) override;
  QString getEditToolDescription(QAction* action) override;

private:
  QAction* edit_ = nullptr;
};

#endif
