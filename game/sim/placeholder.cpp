// placeholder until the simulation lands
