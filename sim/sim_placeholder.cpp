// Empty until the sim layer lands; keeps the library target buildable.
