"""Every circuit drawn and simulated: schematics (schemdraw) and ngspice cross-checks of the book's
equations and of the designs. :mod:`.runner` drives ngspice; :mod:`.circuit` holds the description
every circuit module builds; :mod:`.models` the device models written from the datasheet facts."""
