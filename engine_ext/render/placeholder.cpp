// placeholder until the render glue lands
