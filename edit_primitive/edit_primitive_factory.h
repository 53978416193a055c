// edit_primitive_factory.h: registers the Primitive Edit tool with MeshLab (one toolbar/Edit menu action),
// for the MeshLab generation being built (plugin_api/edit_plugin.h).
#ifndef PRIMITIVE_EDIT_EDIT_PRIMITIVE_FACTORY_H
#define PRIMITIVE_EDIT_EDIT_PRIMITIVE_FACTORY_H

#include "plugin_api/edit_plugin.h"

class EditPrimitiveFactory : public primitive_edit::meshlab::EditPluginAdapter
{
  Q_OBJECT
  PRIMITIVE_EDIT_EDIT_PLUGIN

public:
  EditPrimitiveFactory();

  primitive_edit::meshlab::EditToolAdapter* createTool() override;
  QString description() const override;
};

#endif
